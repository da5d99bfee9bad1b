// Eye-space lighting; gl_TextureMatrix[1] takes eye space to the shadow
// map's [0, 1] coordinates (bias * light projection * light view * inverse(camera view)).
varying vec3 normal;
varying vec4 shadow_coord;
void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    normal = gl_NormalMatrix * gl_Normal;
    shadow_coord = gl_TextureMatrix[1] * eye;
    gl_Position = gl_ProjectionMatrix * eye;
}
