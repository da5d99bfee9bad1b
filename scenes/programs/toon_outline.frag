uniform vec3 ink;
void main() { gl_FragColor = vec4(ink, 1.0); }
