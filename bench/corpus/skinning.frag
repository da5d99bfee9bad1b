varying vec3 lit_color;
varying vec2 uv;
void main() {
    // bands along the tube, to see the bend
    float band = step(0.5, fract(uv.s));
    gl_FragColor = vec4(lit_color * mix(0.8, 1.0, band), 1.0);
}
