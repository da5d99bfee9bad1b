#version 110
// The filtering of 3D, float and depth textures: 1024x512 as 16 bands of 32 rows, sample
// i = (y mod 32) * 1024 + x in [0, 32768). Two-texel black|white textures at u = 0.5 + i / 32768
// (v = the weight of texel 1) and 2D or 3D blends of random texels at positions exact in float.
// Output e = floor(v * 65536 + 1/2) mod 65536 in four nibbles (R the highest), byte 17 * nibble;
// the "low" bands write v * 65536's fraction the same way (the bits a 16-bit result lacks).
//   band 0: 3D 2x1x1, along s          band 1: 3D 1x1x2, along r
//   band 2: rgba32f 2x1, along s       band 3: the same, low bits
//   band 4: depth 2x1 (0|1), along s   band 5: the same, low bits
//   band 6: depth 2x1 (0|1) compared with r = 1/2 (shadow2D), along s
//   band 7: rgba32f 2x1 (1/4 | 3/4), along s: low bits
//   band 8: rgba32f 16x16 random (rand16.png), s = x/1024 + yb/32768, t = yb/32 + x/32768: red
//   band 9: the same, low bits
//   band 10: 3D 2x2x2 octants (rgbw), s = (1/2 + x/1024)/2, t = (1/2 + yb/32 + x/32768)/2,
//            r = (1/2 + fract(i * 37/1024))/2: red      band 11: the same: green
//   band 12: band 8's texture and coordinates: green, low bits
//   band 13: depth 16x16 random (rand16.png's red), band 8's coordinates   band 14: the same, low bits
//   band 15: band 13's texture compared with r = 1/2 (shadow2D)
uniform sampler3D t3s, t3r, t3o;
uniform sampler2D f2, fq, d2, frnd, drnd;
uniform sampler2DShadow d2c, drndc;
vec4 enc(float v) {
    float e = floor(v * 65536.0 + 0.5);
    e = e - 65536.0 * floor(e / 65536.0);
    float n3 = floor(e / 4096.0);
    float n2 = floor(e / 256.0) - 16.0 * n3;
    float n1 = floor(e / 16.0) - 16.0 * floor(e / 256.0);
    float n0 = e - 16.0 * floor(e / 16.0);
    return vec4(n3, n2, n1, n0) * (17.0 / 255.0);
}
float low(float v) { return fract(v * 65536.0); }
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float b = floor(Y / 32.0);
    float yb = Y - b * 32.0;
    float i = yb * 1024.0 + X;
    float u = (0.5 + i / 32768.0) / 2.0;
    vec2 rs = vec2(X / 1024.0 + yb / 32768.0, yb / 32.0 + X / 32768.0);
    vec3 o = vec3(0.5 + X / 1024.0, 0.5 + yb / 32.0 + X / 32768.0, 0.5 + fract(i * (37.0 / 1024.0))) / 2.0;
    float v;
    if (b < 0.5) v = texture3D(t3s, vec3(u, 0.5, 0.5)).r;
    else if (b < 1.5) v = texture3D(t3r, vec3(0.5, 0.5, u)).r;
    else if (b < 2.5) v = texture2D(f2, vec2(u, 0.5)).r;
    else if (b < 3.5) v = low(texture2D(f2, vec2(u, 0.5)).r);
    else if (b < 4.5) v = texture2D(d2, vec2(u, 0.5)).r;
    else if (b < 5.5) v = low(texture2D(d2, vec2(u, 0.5)).r);
    else if (b < 6.5) v = shadow2D(d2c, vec3(u, 0.5, 0.5)).r;
    else if (b < 7.5) v = low(texture2D(fq, vec2(u, 0.5)).r);
    else if (b < 8.5) v = texture2D(frnd, rs).r;
    else if (b < 9.5) v = low(texture2D(frnd, rs).r);
    else if (b < 10.5) v = texture3D(t3o, o).r;
    else if (b < 11.5) v = texture3D(t3o, o).g;
    else if (b < 12.5) v = low(texture2D(frnd, rs).g);
    else if (b < 13.5) v = texture2D(drnd, rs).r;
    else if (b < 14.5) v = low(texture2D(drnd, rs).r);
    else v = shadow2D(drndc, vec3(rs, 0.5)).r;
    gl_FragColor = enc(v);
}
