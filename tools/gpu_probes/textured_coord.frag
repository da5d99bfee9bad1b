#version 400 compatibility
// The GPU only (GLSL 4.00): the bits of textured_pix's interpolated texture
// coordinate (s with the uniform `which` 0, t with 1) as four bytes, most
// significant first, so a decoder can form the derivatives the sampler saw.
uniform sampler2D tex;
uniform int which;

void main()
{
    uint b = floatBitsToUint(gl_TexCoord[0][which]);
    gl_FragColor = vec4(float(b >> 24), float((b >> 16) & 255u), float((b >> 8) & 255u), float(b & 255u)) / 255.0;
}
