#version 400 compatibility
// The GPU only (GLSL 4.00): textured_pix's trilinear lookup, the raw float
// bits of its red (which = 0) or green (1) channel as four bytes, most
// significant first; with textured_s.toml / textured_t.toml.
uniform sampler2D tex;
uniform int which;

void main()
{
    uint b = floatBitsToUint(texture(tex, gl_TexCoord[0].st)[which]);
    gl_FragColor = vec4(float(b >> 24), float((b >> 16) & 255u), float((b >> 8) & 255u), float(b & 255u)) / 255.0;
}
