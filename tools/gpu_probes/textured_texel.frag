// textured_pix's lookup alone (scenes/textured.toml, trilinear): the red and
// green channels of the filtered texel in 16 bits each, as (high byte, low
// byte) pairs, so that a decoder sees the filter's result before the colour
// conversion. Renders on the GPU and in glslrun alike (GLSL 1.10).
uniform sampler2D tex;

vec2 bytes16(float v)
{
    float n = floor(v * 65535.0 + 0.5);
    float high = floor(n / 256.0);
    return vec2(high, n - high * 256.0) / 255.0;
}

void main()
{
    vec4 t = texture2D(tex, gl_TexCoord[0].st);
    gl_FragColor = vec4(bytes16(t.r), bytes16(t.g));
}
