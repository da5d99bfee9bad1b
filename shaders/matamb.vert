void main(void) {

    gl_FrontColor =
        gl_FrontMaterial.ambient;
    gl_Position = ftransform();
}
