#version 110
// The GPU's RGBA8 blend (SRC_ALPHA, ONE_MINUS_SRC_ALPHA), 1024x64: the first draw (mode 0, no
// blending) stores destination bytes, the second (mode 1) blends a source colour c and alpha a over
// them. Per pixel (X, Y): destination bytes R = X mod 256, G = (7X + 3Y) mod 256,
// B = (11X + 5Y + 17) mod 256, A = (3X + Y + 101) mod 256; source values are 16-bit fractions.
// (Measured at 1024x1024 with a / 8 on rows 512-1023, bench/corpus/volume's alphas: the same rule.)
uniform float mode;
float frac16(float k) { return (k - 65536.0 * floor(k / 65536.0)) / 65536.0; }
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    if (mode < 0.5) {
        vec4 d = vec4(X, 7.0 * X + 3.0 * Y, 11.0 * X + 5.0 * Y + 17.0, 3.0 * X + Y + 101.0);
        gl_FragColor = (d - 256.0 * floor(d / 256.0)) / 255.0;
    } else {
        float a = frac16(X * 193.0 + Y * 811.0 + 7.0);
        gl_FragColor = vec4(frac16(X * 1709.0 + Y * 47.0 + 12345.0), frac16(X * 29.0 + Y * 2903.0 + 777.0),
                            frac16(X * 631.0 + Y * 1303.0 + 4242.0), a);
    }
}
