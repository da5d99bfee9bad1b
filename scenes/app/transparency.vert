// Textured, vertex-lit foliage cards and solid objects.
void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    float d = abs(dot(n, normalize(gl_LightSource[0].position.xyz)));
    gl_FrontColor = vec4(gl_Color.rgb * (0.35 + 0.65 * d), gl_Color.a);
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_Position = ftransform();
}
