// A spot light's shadow map: eye space to the map through the texture
// matrix the application loaded (bias * light projection * light view *
// inverse camera view), as the era's shadow demos set it with glLoadMatrix.
varying vec3 normal;
varying vec3 position;
varying vec4 shadow_coord;

void main() {
    vec4 eye_pos = gl_ModelViewMatrix * gl_Vertex;
    position = eye_pos.xyz;
    normal = gl_NormalMatrix * gl_Normal;
    shadow_coord = gl_TextureMatrix[1] * eye_pos;
    gl_Position = ftransform();
}
