#version 110
// fma.frag's follow-up (decode_fma.py fma2): products with several uses, and products by 2.
// Same layout and inputs as fma.frag (a = 1 + u/4096, b = 1 + v/4096, P = 1 + (u + v)/4096, a*b = P +
// u*v/2^24); bands 0-3 store two results of two nibbles each (RG, BA), the others r * 2^24 mod 65536.
float nib(float y, float s) { return floor(fract(y * s) * 16.0) / 15.0; }
vec4 nibbles16(float n) { return vec4(nib(n, 1.0 / 65536.0), nib(n, 1.0 / 4096.0), nib(n, 1.0 / 256.0), nib(n, 1.0 / 16.0)); }
vec4 two(float r1, float r2) {
    return vec4(nib(r1 * 16777216.0, 1.0 / 256.0), nib(r1 * 16777216.0, 1.0 / 16.0),
                nib(r2 * 16777216.0, 1.0 / 256.0), nib(r2 * 16777216.0, 1.0 / 16.0));
}
float mad(float x, float y, float z) { return x * y - z; }
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
    float Q = P + s;
    float r = 0.0;
    if (band < 0.5) {
        float p = a * b;                     // two plain subtractions
        gl_FragColor = two(p - P, p - Q);
        return;
    } else if (band < 1.5) {
        float p = a * b;                     // the same, the other order
        float r2 = p - Q;
        float r1 = p - P;
        gl_FragColor = two(r1, r2);
        return;
    } else if (band < 2.5) {
        float p = a * b;                     // a subtraction, then a subtraction of a subtraction
        gl_FragColor = two(p - P, (p - 1.0) - (u + v) * s);
        return;
    } else if (band < 3.5) {
        float p = a * b;                     // a subtraction and a product by 0.5
        float q = p * 0.5;
        gl_FragColor = two(p - P, q * 2.0 - P);
        return;
    } else if (band < 4.5) {
        float p = a * b;                     // the compare first
        bool k = p > 2.0;
        r = p - P;
        if (k) r = 1.0;
    } else if (band < 5.5) {
        if (gl_FragCoord.x >= 0.0) r = a * b - P;   // product and add inside one block
    } else if (band < 6.5) {
        float t = 2.0 * a;                   // (2a) * b
        r = t * b - 2.0 * P;
    } else if (band < 7.5) {
        r = a * (2.0 * b) - 2.0 * P;         // a * (2b)
    } else if (band < 8.5) {
        r = (a * b) * 2.0 - 2.0 * P;         // (a*b) * 2
    } else if (band < 9.5) {
        r = ((0.5 * a) * b - 0.5 * P) * 2.0; // (a/2) * b, the result doubled (exactly)
    } else if (band < 10.5) {
        r = (3.0 * a) * b - 3.0 * P;         // (3a) * b: 3a is rounded
    } else if (band < 11.5) {
        r = mad(a, b, P);                    // in a function
    } else if (band < 12.5) {
        float p = a * b;                     // the product, then a use of the sum
        r = p - P;
        r = r * 2.0;
    } else if (band < 13.5) {
        r = -(a * b) + P;                    // negated product
    } else if (band < 14.5) {
        r = a * -b + P;                      // product of a negation
    } else {
        r = a * b - P;                       // a*b - c again (a control)
    }
    gl_FragColor = nibbles16(r * 16777216.0);
}
