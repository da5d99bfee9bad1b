#version 110
// bench/corpus/mandelbrot.frag's loop on exact points c (no interpolation): the iteration count n
// as two nibbles (R, G), and |z|^2's nibbles 2^-4 .. 2^-8 after the loop (B, A), on a 256 x 512 grid
// near the set's boundary (decode_fma.py mandel). Band 1 (y >= 256) writes the step in scalars.
uniform int max_iterations;
float nib(float y, float s) { return floor(fract(y * s) * 16.0) / 15.0; }
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float band = floor(Y / 256.0);
    vec2 c = vec2(-0.78 + X / 4096.0, 0.1 + (Y - band * 256.0) / 4096.0);
    vec2 z = vec2(0.0);
    int n = 0;
    for (int i = 0; i < max_iterations; ++i) {
        if (band < 0.5) z = vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y) + c;
        else z = vec2(z.x * z.x - z.y * z.y + c.x, z.x * z.y * 2.0 + c.y);
        if (dot(z, z) > 256.0) break;
        n = n + 1;
    }
    float m = float(n);
    float d = dot(z, z);
    gl_FragColor = vec4(floor(m / 16.0) / 15.0, (m - floor(m / 16.0) * 16.0) / 15.0, nib(d, 1.0 / 16.0), nib(d, 1.0 / 256.0));
}
