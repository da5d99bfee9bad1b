// A floor that recedes to the horizon: the texture is minified more and more
// with distance, so every mipmap level is used (trilinear filtering).
varying vec2 uv;
varying float dist;
void main() {
    uv = (gl_TextureMatrix[0] * gl_MultiTexCoord0).st;
    dist = length(vec3(gl_ModelViewMatrix * gl_Vertex));
    gl_Position = ftransform();
}
