void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    float d = max(dot(n, normalize(vec3(0.3, 0.8, 0.6))), 0.0);
    gl_FrontColor = vec4(gl_Color.rgb * (0.3 + 0.7 * d), gl_Color.a);
    gl_Position = ftransform();
}
