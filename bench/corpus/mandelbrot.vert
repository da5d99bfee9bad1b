// The Mandelbrot set on a full-screen quad, coloured through a 1D palette.
uniform vec2 center;
uniform float scale;
uniform float aspect;
varying vec2 c;
void main() {
    c = center + gl_Vertex.xy * vec2(aspect, 1.0) * scale;
    gl_Position = gl_Vertex;
}
