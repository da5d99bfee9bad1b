// A full-screen quad; the fragment shader traces one ray per pixel.
varying vec2 screen;   // [-1, 1] across the quad
void main() {
    screen = gl_Vertex.xy;
    gl_Position = gl_Vertex;
}
