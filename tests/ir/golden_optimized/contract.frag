// Multiply-add contraction (ir/contract.cpp): the shapes measured on the GPU.
uniform vec2 c;
void main() {
    vec2 z = gl_FragCoord.xy;
    float p = z.x * z.y;
    float one = p - c.x;               // ffms, and p has a second add
    float two = c.y - p;               // ffnma: p itself goes
    float q = z.x * c.x;
    float kept = q + c.y;              // q is also compared: rounded
    if (q > 1.0) kept = 0.0;
    vec2 m = vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y) + c;  // mandelbrot's step
    gl_FragColor = vec4(one, two, kept, dot(m, vec2(1.0, z.y)));  // 1.0 * m.x: not a product
}
