// --check-undefined in the vertex stage: sqrt of x < 0 at the quad's two
// left corners (x = -1), 2 vertices (tests/cli/check_undefined.sh).
varying float s;
void main() {
    s = sqrt(gl_Vertex.x);
    gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0);
}
