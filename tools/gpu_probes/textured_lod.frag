#version 400 compatibility
// The GPU only (GLSL 4.00): textured_pix's level of detail as the sampler
// computes it (textureQueryLod's y, lambda before the level clamp; x, the
// level accessed), each as 256 lambda + 32768 in 16 bits (high, low byte).
uniform sampler2D tex;

vec2 bytes16(float v)
{
    float n = floor(v * 256.0 + 0.5) + 32768.0;
    float high = floor(n / 256.0);
    return vec2(high, n - high * 256.0) / 255.0;
}

void main()
{
    vec2 q = textureQueryLod(tex, gl_TexCoord[0].st);
    gl_FragColor = vec4(bytes16(q.y), bytes16(q.x));
}
