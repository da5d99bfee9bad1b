#version 400 compatibility
// The GPU only (GLSL 4.00): the raw float bits of textureQueryLod(...).y
// (lambda before the level clamp) of textured_pix's lookup, four bytes.
uniform sampler2D tex;

void main()
{
    uint b = floatBitsToUint(textureQueryLod(tex, gl_TexCoord[0].st).y);
    gl_FragColor = vec4(float(b >> 24), float((b >> 16) & 255u), float((b >> 8) & 255u), float(b & 255u)) / 255.0;
}
