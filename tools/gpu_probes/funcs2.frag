#version 110
// The absolute float32 error of sin, cos, exp and log, read through an RGBA8 image as
// ../shared/tools/gpu/probe/funcs.frag does: 8 bands of 64 rows, sample i = (y mod 64) * 512 + x,
// y's bits from 2^-13 to 2^-24 as three nibbles (R bits 0-3 of y * 2^20, G of y * 2^16, B of
// y * 2^12), byte 17 * nibble (decode.py funcs2). Arguments are exact in float (no rounding
// the compiler could fuse away).
float nib(float y, float s) { return floor(fract(y * s) * 16.0) / 15.0; }
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float b = floor(Y / 64.0);
    float i = (Y - b * 64.0) * 512.0 + X;
    float y;
    if (b < 0.5) y = sin(0.5 + i / 32768.0);          // x in [0.5, 1.5)
    else if (b < 1.5) y = cos(i / 32768.0);           // x in [0, 1)
    else if (b < 2.5) y = sin(2.0 + i / 32768.0);     // x in [2, 3)
    else if (b < 3.5) y = cos(4.0 + i / 16384.0);     // x in [4, 6): y in [-0.65, 0.96]
    else if (b < 4.5) y = exp(-i / 32768.0);          // x in (-1, 0]
    else if (b < 5.5) y = log(1.75 + i / 32768.0);    // x in [1.75, 2.75)
    else if (b < 6.5) y = sin(64.0 + i / 256.0);      // x in [64, 192)
    else y = cos(-64.0 - i / 256.0);                  // x in (-192, -64]
    gl_FragColor = vec4(nib(y, 1048576.0), nib(y, 65536.0), nib(y, 4096.0), 1.0);
}
