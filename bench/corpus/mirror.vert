// One program for every pass of the stencilled mirror: per-pixel lighting
// of the light in gl_LightSource[0], and a uniform alpha for the mirror.
varying vec3 normal, position;
void main() {
    normal = gl_NormalMatrix * gl_Normal;
    position = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_Position = ftransform();
}
