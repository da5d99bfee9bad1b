// A base texture on unit 0 and a decal with alpha on unit 1, each with its
// own coordinates (the decal's through gl_TextureMatrix[1]), per-vertex
// diffuse lighting.
varying float diffuse;
void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    diffuse = max(dot(n, l), 0.0);
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_TexCoord[1] = gl_TextureMatrix[1] * gl_MultiTexCoord0;
    gl_Position = ftransform();
}
