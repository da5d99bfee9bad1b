// Toon shading: the diffuse intensity picks one of four bands of a ramp
// (a 1D texture, nearest), with a dark outline where the surface turns away
// from the viewer and a hard specular spot.
varying vec3 normal, position;
void main() {
    normal = gl_NormalMatrix * gl_Normal;
    position = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_Position = ftransform();
}
