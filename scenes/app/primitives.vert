void main() {
    gl_FrontColor = gl_Color;
    gl_BackColor = vec4(1.0 - gl_Color.rgb, 1.0);
    gl_Position = ftransform();
}
