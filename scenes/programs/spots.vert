// Several per-pixel spot lights in a uniform array of structs, each with
// GL's attenuation and spot exponent, over a floor and two objects.
varying vec3 normal;
varying vec3 position;

void main() {
    position = vec3(gl_ModelViewMatrix * gl_Vertex);
    normal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
