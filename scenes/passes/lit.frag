varying vec3 normal;
void main() {
    float d = max(dot(normalize(normal), normalize(gl_LightSource[0].position.xyz)), 0.0);
    gl_FragColor = vec4(gl_Color.rgb * (0.25 + 0.75 * d), 1.0);
}
