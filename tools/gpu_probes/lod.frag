#version 110
// Level-of-detail probe: 8 bands of 64 rows; in each band 2x2 quads q = (yb / 2) * 256 + x / 2 in
// [0, 8192). Within a quad the coordinates are 0 or an exact step a, so the derivatives are exact:
// rho = 256 a (1 + q / 8192) 2^m, lambda = m + log2(1 + q / 8192) (+ 1/2 where both s and t step along x).
// The mipmapped textures have 256x256 level 0; level k >= 1 is solid (k/15, k mod 2, 0) (decode.py lod):
// bands 0-4 write green (the blend's fraction at 16 bits), bands 4-7 red (which level).
//   band 0: lvl (level 0 solid 0), LINEAR_MIPMAP_LINEAR, m = 0
//   band 1: lvl, LINEAR_MIPMAP_LINEAR, m = 1
//   band 2: lvl, LINEAR_MIPMAP_LINEAR, m = 0, s and t both step along x (rho = sqrt 2 * 256 a?)
//   band 3: lvl, LINEAR_MIPMAP_LINEAR, m = 0, t steps 3/4 a along y (rho = max of the two?)
//   band 4: lvl, LINEAR_MIPMAP_LINEAR, s = px * a * (1 + py): ds/dx is a in the quad's lower row and 2a in
//           its upper one, ds/dy 0 in its left column and a in its right (coarse or fine derivatives?)
//   band 5: chk, NEAREST_MIPMAP_NEAREST, mag LINEAR, m = 0 (the switch-over c)
//   band 6: chk2 (the same levels), NEAREST_MIPMAP_LINEAR, mag LINEAR, m = 0
//   band 7: lvl2 (the same levels as lvl), LINEAR_MIPMAP_NEAREST, m = 0 (the level switch at 1/2)
// Output as texfilter.frag's: e = floor(v * 65536 + 1/2) in four nibbles.
uniform sampler2D lvl, lvl2, chk, chk2;
vec4 enc(float v) {
    float e = floor(v * 65536.0 + 0.5);
    e = e - 65536.0 * floor(e / 65536.0);
    float n3 = floor(e / 4096.0);
    float n2 = floor(e / 256.0) - 16.0 * n3;
    float n1 = floor(e / 16.0) - 16.0 * floor(e / 256.0);
    float n0 = e - 16.0 * floor(e / 16.0);
    return vec4(n3, n2, n1, n0) * (17.0 / 255.0);
}
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float b = floor(Y / 64.0);
    float yb = Y - b * 64.0;
    float q = floor(yb / 2.0) * 256.0 + floor(X / 2.0);
    float px = X - 2.0 * floor(X / 2.0);
    float py = Y - 2.0 * floor(Y / 2.0);
    float m = b > 0.5 && b < 1.5 ? 2.0 : 1.0;
    float a = (1.0 + q / 8192.0) * m / 256.0;
    vec2 st = vec2(px * a, py * a);
    if (b > 1.5 && b < 2.5) st = vec2(px * a, px * a);
    if (b > 2.5 && b < 3.5) st = vec2(px * a, py * a * 0.75);
    if (b > 3.5 && b < 4.5) st = vec2(px * a * (1.0 + py), 0.0);
    vec4 t;
    if (b < 4.5) t = texture2D(lvl, st);
    else if (b < 5.5) t = texture2D(chk, st);
    else if (b < 6.5) t = texture2D(chk2, st);
    else t = texture2D(lvl2, st);
    gl_FragColor = enc(b < 4.5 ? t.g : t.r);
}
