#version 110
// The GPU's rho for a 3D texture: 1024x512, quad q = (y/2) * 512 + x/2 in [0, 131072); for
// q < 7^6 = 117649 its texel-space derivatives (du, dv, dw)/dx and /dy are c(digit j of q in base 7),
// j = 0..5, c(k) = (k - 3) * 1.5. lod3d.toml's texture: 64^3, level k solid (k/15, k mod 2, 0),
// LINEAR_MIPMAP_LINEAR. Output as lodnorm.frag (red: the level pair, green's blend at 12 bits).
uniform sampler3D lvl;
float digit(float q, float p) { return floor(q / p) - 7.0 * floor(q / (7.0 * p)); }
float c(float k) { return (k - 3.0) * 1.5; }
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float q = floor(Y / 2.0) * 512.0 + floor(X / 2.0);
    float px = X - 2.0 * floor(X / 2.0);
    float py = Y - 2.0 * floor(Y / 2.0);
    vec3 dx = vec3(c(digit(q, 1.0)), c(digit(q, 7.0)), c(digit(q, 49.0)));
    vec3 dy = vec3(c(digit(q, 343.0)), c(digit(q, 2401.0)), c(digit(q, 16807.0)));
    vec4 t = texture3D(lvl, (px * dx + py * dy) / 64.0 + vec3(0.5 / 64.0));
    float e = floor(t.g * 4096.0 + 0.5);
    e = e - 4096.0 * floor(e / 4096.0);
    float n2 = floor(e / 256.0);
    float n1 = floor(e / 16.0) - 16.0 * n2;
    float n0 = e - 16.0 * floor(e / 16.0);
    gl_FragColor = vec4(t.r, n2 * (17.0 / 255.0), n1 * (17.0 / 255.0), n0 * (17.0 / 255.0));
}
