varying float s;
void main() { gl_FragColor = vec4(s); }
