void main() {
    gl_FragData[0] = gl_Color;
    gl_FragData[1] = gl_Color.abgr;
}
