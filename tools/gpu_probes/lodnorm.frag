#version 110
// The GPU's rho for derivative vectors off the axes: 8 bands of 64 rows, 2x2 quads
// q = (yb / 2) * 256 + x / 2 in [0, 8192), r = q / 8192. Along x, (du, dv) = 256 a (1, r) (bands
// 0-3: a = m / 256 for m = 1, 1.25, 1.5, 1.75), (r, 1) (band 4), along y (1, r) (band 5); band 6:
// d/dx = 256 a (1, r) and d/dy = 256 a (r, 1) with m = 1; band 7: (1, r) with m = 2.
// lod.toml's texture lvl (level k solid (k/15, k mod 2, 0)), LINEAR_MIPMAP_LINEAR. Output: red as
// sampled (the level pair: floor(red * 15)), green's blend at 12 bits in G, B, A nibbles (decode.py lodnorm).
uniform sampler2D lvl, lvl2, chk, chk2;
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float b = floor(Y / 64.0);
    float yb = Y - b * 64.0;
    float q = floor(yb / 2.0) * 256.0 + floor(X / 2.0);
    float px = X - 2.0 * floor(X / 2.0);
    float py = Y - 2.0 * floor(Y / 2.0);
    float r = q / 8192.0;
    float m = b < 0.5 ? 1.0 : (b < 1.5 ? 1.25 : (b < 2.5 ? 1.5 : (b < 3.5 ? 1.75 : (b < 6.5 ? 1.0 : 2.0))));
    float a = m / 256.0;
    vec2 st = vec2(px * a, px * a * r);
    if (b > 3.5 && b < 4.5) st = vec2(px * a * r, px * a);
    if (b > 4.5 && b < 5.5) st = vec2(py * a, py * a * r);
    if (b > 5.5 && b < 6.5) st = vec2(px * a + py * a * r, px * a * r + py * a);
    vec4 t = texture2D(lvl, st);
    float e = floor(t.g * 4096.0 + 0.5);
    e = e - 4096.0 * floor(e / 4096.0);
    float n2 = floor(e / 256.0);
    float n1 = floor(e / 16.0) - 16.0 * n2;
    float n0 = e - 16.0 * floor(e / 16.0);
    gl_FragColor = vec4(t.r, n2 * (17.0 / 255.0), n1 * (17.0 / 255.0), n0 * (17.0 / 255.0));
}
