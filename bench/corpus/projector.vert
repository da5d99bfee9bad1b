// A slide projector: texture coordinates from the eye-space position through
// gl_TextureMatrix[1] (bias * projector projection * projector view *
// inverse camera view, what glTexGen(GL_EYE_LINEAR) with the texture matrix
// gave fixed-function programs), then texture2DProj.
varying vec4 projector_coord;
varying vec3 normal, position;
void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    position = eye.xyz;
    normal = gl_NormalMatrix * gl_Normal;
    projector_coord = gl_TextureMatrix[1] * eye;
    gl_Position = gl_ProjectionMatrix * eye;
}
