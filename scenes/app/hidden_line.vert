// Flat-coloured objects with a head light, for hidden-line drawings.
void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    gl_FrontColor = vec4(gl_Color.rgb * (0.3 + 0.7 * abs(n.z)), gl_Color.a);
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_Position = ftransform();
}
