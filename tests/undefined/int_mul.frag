// --check-undefined: int multiplication past 32 bits: x = 0, 1, 6, 7, 32 pixels (tests/cli/check_undefined.sh; t = x - 4, u = y)
uniform int zi;
void main() {
    float t = floor(gl_FragCoord.x) - 4.0, u = floor(gl_FragCoord.y); int x = int(t) + 4; float r = 0.0; int ri = 0;
    ri = (1073741824 + zi) * (x - 4);
    gl_FragColor = vec4(r, float(ri), 0.0, 1.0);
}
