// Discards yellow fragments, so that one object of fragment_tests.toml
// stops in the shader; the others meet the per-fragment tests.
void main(void) {
    if (gl_Color.r > 0.5 && gl_Color.g > 0.5)
        discard;
    gl_FragColor = gl_Color;
}
