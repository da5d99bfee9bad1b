#version 110
// Texture filtering probe: 8 bands of 64 rows, sample i = (y mod 64) * 512 + x in [0, 32768).
// Each band samples one texture at coordinates that are exact in float (powers of two), so a
// decoder (tools/gpu_probes/decode.py) knows u = s * size exactly. The result v in [0, 1] is written
// as e = floor(v * 65536 + 1/2) mod 65536 in four nibbles (R the highest), each as byte 17 * nibble.
//   band 0: 2x1 black|white, LINEAR, u = 0.5 + i / 32768        (v = the weight of texel 1)
//   band 1: 64x1 checkerboard, LINEAR, u = 31.5 + i / 32768      (v = 1 - weight of texel 32)
//   band 2: 4096x1 checkerboard, LINEAR, u = 2047.5 + i / 32768  (v = 1 - weight of texel 2048)
//   band 3: 256x1 ramp (texel k = k/255), NEAREST, u = 128 + (i - 16384) / 65536
//   band 4: 16x16 random RGBA, LINEAR, REPEAT, s = x/512 + yb/32768, t = yb/64 + x/16384: red
//   band 5: the same: green
//   band 6: 1x2 black|white (along t), LINEAR, v = 0.5 + i / 32768 (v = the weight of texel 1)
//   band 7: 2x1 black|white, LINEAR, u = -0.5 + i / 16384 (the clamp at the edges and beyond)
uniform sampler2D w2, w64, w4096, ramp, rnd, w2t;
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
    float i = yb * 512.0 + X;
    float v;
    if (b < 0.5) v = texture2D(w2, vec2((0.5 + i / 32768.0) / 2.0, 0.5)).r;
    else if (b < 1.5) v = texture2D(w64, vec2((31.5 + i / 32768.0) / 64.0, 0.5)).r;
    else if (b < 2.5) v = texture2D(w4096, vec2((2047.5 + i / 32768.0) / 4096.0, 0.5)).r;
    else if (b < 3.5) v = texture2D(ramp, vec2((128.0 + (i - 16384.0) / 65536.0) / 256.0, 0.5)).r;
    else if (b < 4.5) v = texture2D(rnd, vec2(X / 512.0 + yb / 32768.0, yb / 64.0 + X / 16384.0)).r;
    else if (b < 5.5) v = texture2D(rnd, vec2(X / 512.0 + yb / 32768.0, yb / 64.0 + X / 16384.0)).g;
    else if (b < 6.5) v = texture2D(w2t, vec2(0.5, (0.5 + i / 32768.0) / 2.0)).r;
    else v = texture2D(w2, vec2((-0.5 + i / 16384.0) / 2.0, 0.5)).r;
    gl_FragColor = enc(v);
}
