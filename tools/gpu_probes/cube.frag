#version 110
// Cube-map coordinate probe: the +X face (2x2, columns black | white, LINEAR, CLAMP_TO_EDGE) looked
// up along r = (ma, 0, -sc), so s = (sc / ma + 1) / 2 and the weight of the white column is
// sc / ma + 1/2 for sc in [-ma/2, ma/2): 8 bands of 64 rows, one |ma| each, sample
// i = (y mod 64) * 512 + x, sc = ma * (i / 32768 - 1/2), all exact in float for whole ma.
// Output as texfilter.frag's: e = floor(v * 65536 + 1/2) in four nibbles (decode.py cube).
uniform samplerCube env;
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
    float i = (Y - b * 64.0) * 512.0 + X;
    float ma = b < 0.5 ? 1.0 : (b < 1.5 ? 3.0 : (b < 2.5 ? 5.0 : (b < 3.5 ? 7.0 :
               (b < 4.5 ? 11.0 : (b < 5.5 ? 13.0 : (b < 6.5 ? 0.75 : 2.0))))));
    float sc = ma * (i / 32768.0) - ma * 0.5;
    gl_FragColor = enc(textureCube(env, vec3(ma, 0.0, -sc)).r);
}
