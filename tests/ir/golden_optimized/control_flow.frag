uniform int n;
float sq(float x) { return x * x; }
void main() {
    float s = 0.0;
    for (int k = 0; k < n; k++) {
        if (k == 3) continue;
        s += sq(float(k));
    }
    if (s > 10.0 && n > 2) discard;
    gl_FragColor = vec4(s);
}
