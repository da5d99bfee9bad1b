// A full-screen quad whose vertex colour is out of [0, 1]: GL clamps it
// (GL_CLAMP_VERTEX_COLOR_ARB is TRUE), float target or not.
void main() { gl_FrontColor = vec4(2.0, 0.5, -1.0, 1.0); gl_Position = gl_Vertex; }
