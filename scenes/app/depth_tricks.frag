// tint.a > 0: a flat colour (the x-ray silhouette, the sky).
uniform vec4 tint;
void main() {
    gl_FragColor = tint.a > 0.0 ? tint : gl_Color;
}
