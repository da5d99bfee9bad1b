#version 120
uniform sampler2D tex;
struct S { vec3 a; float b[3]; };
float f(float x) { return x > 0.5 ? sin(x) : pow(x, 2.0); }
void main() {
    S s = S(vec3(1.0), float[3](1.0, 2.0, 3.0));
    vec4 c = vec4(0.0);
    for (int i = 0; i < 4; ++i) { if (i == 2) continue; c += texture2D(tex, gl_FragCoord.xy / 8.0) * f(s.b[i % 3]); }
    if (c.x < 0.0) discard;
    gl_FragColor = c + vec4(s.a, 1.0) * dFdx(gl_FragCoord.x);
}
