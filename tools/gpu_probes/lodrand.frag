#version 110
// The GPU's rho for arbitrary derivatives: 1024x512, 2x2 quads (qx, qy) = (x/2, y/2); in each half
// (h = qx / 256) quad q = qy * 256 + (qx mod 256) in [0, 65536) has the texel-space derivatives
// du/dx = c(q mod 16), dv/dx = c(q/16 mod 16), du/dy = c(q/256 mod 16), dv/dy = c(q/4096),
// c(k) = (k - 7.5) * m with m = 1 (left half) or 1.375 (right half): every sign and ratio.
// lod.toml's texture lvl (level k solid (k/15, k mod 2, 0)), LINEAR_MIPMAP_LINEAR. Output as
// lodnorm.frag: red as sampled (the level pair), green's blend at 12 bits in G, B, A nibbles.
uniform sampler2D lvl;
float c(float k, float m) { return (k - 7.5) * m; }
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float qx = floor(X / 2.0);
    float h = floor(qx / 256.0);
    float q = floor(Y / 2.0) * 256.0 + qx - 256.0 * h;
    float px = X - 2.0 * qx;
    float py = Y - 2.0 * floor(Y / 2.0);
    float m = h < 0.5 ? 1.0 : 1.375;
    float k0 = q - 16.0 * floor(q / 16.0);
    float k1 = floor(q / 16.0) - 16.0 * floor(q / 256.0);
    float k2 = floor(q / 256.0) - 16.0 * floor(q / 4096.0);
    float k3 = floor(q / 4096.0);
    vec2 st = (px * vec2(c(k0, m), c(k1, m)) + py * vec2(c(k2, m), c(k3, m))) / 256.0;
    vec4 t = texture2D(lvl, st);
    float e = floor(t.g * 4096.0 + 0.5);
    e = e - 4096.0 * floor(e / 4096.0);
    float n2 = floor(e / 256.0);
    float n1 = floor(e / 16.0) - 16.0 * n2;
    float n0 = e - 16.0 * floor(e / 16.0);
    gl_FragColor = vec4(t.r, n2 * (17.0 / 255.0), n1 * (17.0 / 255.0), n0 * (17.0 / 255.0));
}
