// The lit scene drawn into the first render target.
varying vec3 normal;
varying vec3 position;
void main() {
    position = vec3(gl_ModelViewMatrix * gl_Vertex);
    normal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
