// Texgen in a vertex shader as GL's fixed function computes it: object-
// linear s and t for the ground's checks (the planes as uniforms, the same
// as the fixed-function teapot's glTexGen planes), eye-linear coordinates
// for a slide projector, each through its texture matrix, into gl_TexCoord[].
uniform vec4 object_planes[2];
uniform mat4 eye_planes;   // rows s, t, r, q: the columns of its transpose

varying vec3 normal;
varying vec3 position;

void main() {
    vec4 eye_pos = gl_ModelViewMatrix * gl_Vertex;
    position = eye_pos.xyz;
    normal = gl_NormalMatrix * gl_Normal;
    vec4 object_coords = vec4(dot(gl_Vertex, object_planes[0]), dot(gl_Vertex, object_planes[1]), 0.0, 1.0);
    vec4 eye_coords = eye_pos * eye_planes;
    gl_TexCoord[0] = gl_TextureMatrix[0] * object_coords;
    gl_TexCoord[1] = gl_TextureMatrix[1] * eye_coords;
    gl_Position = ftransform();
}
