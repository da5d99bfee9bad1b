uniform sampler1D palette;
uniform int max_iterations;
varying vec2 c;
void main() {
    vec2 z = vec2(0.0);
    int n = 0;
    for (int i = 0; i < max_iterations; ++i) {
        z = vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y) + c;
        if (dot(z, z) > 256.0) break;
        n = n + 1;
    }
    if (n == max_iterations) {
        gl_FragColor = vec4(0.0, 0.0, 0.0, 1.0);
    } else {
        // smooth iteration count
        float smooth_n = float(n) + 1.0 - log2(log2(dot(z, z)) * 0.5);
        gl_FragColor = texture1D(palette, smooth_n * 0.03);
    }
}
