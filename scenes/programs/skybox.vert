// A sky box: the cube's own object-space position is the direction.
varying vec3 direction;
void main() {
    direction = gl_Vertex.xyz;
    gl_Position = ftransform();
}
