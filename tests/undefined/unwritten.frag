// --check-undefined: a read of a variable never written: x = 0..3, 32 pixels (tests/cli/check_undefined.sh; t = x - 4, u = y)
uniform int zi;
void main() {
    float t = floor(gl_FragCoord.x) - 4.0, u = floor(gl_FragCoord.y); int x = int(t) + 4; float r = 0.0; int ri = 0;
    float v; if (t >= 0.0) v = 1.0; r = v;
    gl_FragColor = vec4(r, float(ri), 0.0, 1.0);
}
