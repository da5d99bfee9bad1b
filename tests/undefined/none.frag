// --check-undefined finds nothing here: every operation is defined for the
// operands it gets (tests/cli/check_undefined.sh).
void main() {
    float t = floor(gl_FragCoord.x) - 4.0, u = floor(gl_FragCoord.y);
    gl_FragColor = vec4(pow(max(t, 0.0), 2.0) + sqrt(abs(t)) + log(u + 1.0) + clamp(u, 0.0, 1.0), 0.0, 0.0, 1.0);
}
