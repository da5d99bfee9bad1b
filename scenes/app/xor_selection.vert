void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    gl_FrontColor = vec4(gl_Color.rgb * (0.25 + 0.75 * max(n.z, 0.0)), 1.0);
    gl_Position = ftransform();
}
