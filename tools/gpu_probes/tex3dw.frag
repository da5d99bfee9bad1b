#version 110
// The eight weights of a trilinear (3D LINEAR) lookup: 1024x512 as 8 bands of 64 rows. Band b
// samples texture b at 16-bit fractions (fx, fy, fz) of texel 0 towards texel 1 on each axis of a
// 2x2x2 texture, the same 65,536 in every band (ties of the 8-bit weights among them).
// Textures 0-6 are the Walsh patterns (x, y, z, x^y, x^z, y^z, x^y^z: black where the parity is
// even, white where odd), whose seven sums give every texel's weight; texture 7 is x^y^z with
// colours of other bytes (texels as 16-bit values). Output: e = floor(v * 65536 + 1/2) mod 65536
// of the red channel, four nibbles (R the highest) as byte 17 * nibble.
uniform sampler3D p0, p1, p2, p3, p4, p5, p6, p7;
vec4 enc(float v) {
    float e = floor(v * 65536.0 + 0.5);
    e = e - 65536.0 * floor(e / 65536.0);
    float n3 = floor(e / 4096.0);
    float n2 = floor(e / 256.0) - 16.0 * n3;
    float n1 = floor(e / 16.0) - 16.0 * floor(e / 256.0);
    float n0 = e - 16.0 * floor(e / 16.0);
    return vec4(n3, n2, n1, n0) * (17.0 / 255.0);
}
// Exact in float: every product below stays under 2^24, and 65536 is a power of two.
float frac16(float k) { return (k - 65536.0 * floor(k / 65536.0)) / 65536.0; }
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float b = floor(Y / 64.0);
    float yb = Y - 64.0 * b;
    float p = b;
    vec3 f = vec3(frac16(X * 193.0 + yb * 811.0 + 7.0), frac16(X * 1709.0 + yb * 47.0 + 12345.0),
                  frac16(X * 29.0 + yb * 2903.0 + 777.0));
    vec3 c = (0.5 + f) / 2.0;
    float v;
    if (p < 0.5) v = texture3D(p0, c).r;
    else if (p < 1.5) v = texture3D(p1, c).r;
    else if (p < 2.5) v = texture3D(p2, c).r;
    else if (p < 3.5) v = texture3D(p3, c).r;
    else if (p < 4.5) v = texture3D(p4, c).r;
    else if (p < 5.5) v = texture3D(p5, c).r;
    else if (p < 6.5) v = texture3D(p6, c).r;
    else v = texture3D(p7, c).r;
    gl_FragColor = enc(v);
}
