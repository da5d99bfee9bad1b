// --check-undefined: an array index out of range: x = 0, 1, 6, 7, 32 pixels (tests/cli/check_undefined.sh; t = x - 4, u = y)
uniform int zi;
void main() {
    float t = floor(gl_FragCoord.x) - 4.0, u = floor(gl_FragCoord.y); int x = int(t) + 4; float r = 0.0; int ri = 0;
    float a[4]; a[0] = 1.0; a[1] = 2.0; a[2] = 3.0; a[3] = 4.0; r = a[x - 2];
    gl_FragColor = vec4(r, float(ri), 0.0, 1.0);
}
