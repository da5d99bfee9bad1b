uniform vec4 u;
void main() {
    vec4 v = u;
    v.zx = v.xz;
    gl_FragColor = v;
}
