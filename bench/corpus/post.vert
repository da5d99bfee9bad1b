// A full-screen post-process pass: the quad in clip space, texture
// coordinates from its corners.
varying vec2 uv;
void main() {
    uv = gl_Vertex.xy * 0.5 + 0.5;
    gl_Position = gl_Vertex;
}
