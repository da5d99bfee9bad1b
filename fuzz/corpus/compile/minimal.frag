void main(void) {
    gl_FragColor = vec4(1,0,0,1);
}
