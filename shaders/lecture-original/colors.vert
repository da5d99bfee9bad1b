// Vertex Shader

void main(void) {

    glColor = gl_Color;
    gl_Position = ftransform();
}
