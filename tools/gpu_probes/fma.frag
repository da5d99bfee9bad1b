#version 110
// Which multiply-adds the compiler fuses into one rounding (decode_fma.py). 16 bands of 32 rows,
// 256 columns: u = x (0..255), v = 1 + 8 * (y mod 32). a = 1 + u/4096 and b = 1 + v/4096 are exact,
// and so is P = 1 + (u + v)/4096; a*b = P + u*v/2^24 exactly, which float rounds to a multiple of
// 2^-23. So a*b - P is u*v/2^24 when fused and the product's rounding error otherwise. Every other
// operation here is exact (products by powers of two, sums on the same grid), so only the fusion of
// the product under test can change a bit. Each pixel stores r * 2^24 mod 65536 as four nibbles
// (R the highest, byte 17 * nibble), except band 3 (two results, two nibbles each).
float nib(float y, float s) { return floor(fract(y * s) * 16.0) / 15.0; }
vec4 nibbles16(float n) { return vec4(nib(n, 1.0 / 65536.0), nib(n, 1.0 / 4096.0), nib(n, 1.0 / 256.0), nib(n, 1.0 / 16.0)); }
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float band = floor(Y / 32.0);
    float u = X;
    float v = 1.0 + 8.0 * (Y - band * 32.0);
    float s = 1.0 / 4096.0;
    float a = 1.0 + u * s;
    float b = 1.0 + v * s;
    float P = 1.0 + (u + v) * s;
    float r = 0.0;
    if (band < 0.5) {
        r = a * b - P;                                   // a*b - c
    } else if (band < 1.5) {
        float c = -P;
        r = a * b + c;                                   // a*b + c
    } else if (band < 2.5) {
        r = P - a * b;                                   // c - a*b
    } else if (band < 3.5) {
        float p = a * b;                                 // one product, two adds
        float r1 = p - P;
        float r2 = (p - 1.0) - (u + v) * s;
        gl_FragColor = vec4(nib(r1 * 16777216.0, 1.0 / 256.0), nib(r1 * 16777216.0, 1.0 / 16.0),
                            nib(r2 * 16777216.0, 1.0 / 256.0), nib(r2 * 16777216.0, 1.0 / 16.0));
        return;
    } else if (band < 4.5) {
        float p = a * b;                                 // an add and a compare
        r = p - P;
        if (p > 2.0) r = 1.0;
    } else if (band < 5.5) {
        float p = a * b;                                 // the add in another block
        if (gl_FragCoord.x >= 0.0) r = p - P;
    } else if (band < 6.5) {
        r = dot(vec2(a, 1.0), vec2(b, -P));              // dot, the product first
    } else if (band < 7.5) {
        r = dot(vec2(1.0, a), vec2(-P, b));              // dot, the product second
    } else if (band < 8.5) {
        r = dot(vec3(1.0, 0.5, a), vec3(-P, 0.0, b));    // dot3, the product last
    } else if (band < 9.5) {
        r = dot(vec4(a, 1.0, 0.0, 0.0), vec4(b, -P, 0.0, 0.0));  // dot4, the product first
    } else if (band < 10.5) {
        r = (mat2(a, 0.0, 1.0, 0.0) * vec2(b, -P)).x;    // mat2 * vec2
    } else if (band < 11.5) {
        r = mix(-P, a - P, b);                           // mix(x, y, t): y - x = a exactly
    } else if (band < 12.5) {
        r = (vec3(a, a, 1.0) * vec3(b, b, 1.0) + vec3(-P)).y;  // vector multiply, vector add
    } else if (band < 14.5) {
        vec2 z = vec2(a, b);                             // mandelbrot's step
        vec2 c = vec2(-(u - v) * (2.0 * s), -2.0 * P);
        z = vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y) + c;
        r = band < 13.5 ? z.x : z.y;
    } else {
        float a2 = -(1.0 + (u + 1.0) * s);               // two inexact products
        float b2 = 1.0 + v * s;
        r = a * b + a2 * b2;
    }
    gl_FragColor = nibbles16(r * 16777216.0);
}
