// A full-screen quad: the position is the clip-space corner, texture
// coordinates from it.
varying vec2 uv;
void main() {
    uv = gl_Vertex.xy * 0.5 + 0.5;
    gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0);
}
