// Per-pixel lighting from GL_LIGHT0 for stencil shadow volumes: the same
// program draws the ambient pass and the light's additive pass, so that the
// second pass's depth equals the first's (ftransform is invariant).
varying vec3 normal;
varying vec3 to_light;
void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    normal = gl_NormalMatrix * gl_Normal;
    to_light = gl_LightSource[0].position.xyz - eye.xyz;
    gl_FrontColor = gl_Color;
    gl_Position = ftransform();
}
