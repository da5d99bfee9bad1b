// Marble: a sine of the object-space x, disturbed by turbulence (a sum of
// octaves of hand-written gradient noise), lit per pixel.
uniform float noise_scale;
varying vec3 object_position;
varying vec3 normal, position;
void main() {
    object_position = gl_Vertex.xyz * noise_scale;
    position = vec3(gl_ModelViewMatrix * gl_Vertex);
    normal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
