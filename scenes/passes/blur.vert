// A full-screen quad (the identity camera): texture coordinates as given.
void main() {
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_Position = gl_Vertex;
}
