uniform int i;
uniform float a[3];
void main() {
    vec2 t[2];
    t[i] = vec2(a[i]);
    gl_FragColor = vec4(t[1 - i], 0.0, 1.0);
}
