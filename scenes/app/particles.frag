#version 120
// A soft disc from gl_PointCoord, premultiplied for additive blending.
void main() {
    vec2 p = gl_PointCoord * 2.0 - 1.0;
    float r2 = dot(p, p);
    if (r2 > 1.0) discard;
    float a = gl_Color.a * (1.0 - r2);
    gl_FragColor = vec4(gl_Color.rgb * a, a);
}
