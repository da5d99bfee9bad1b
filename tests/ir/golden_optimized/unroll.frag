// ir/unroll.cpp: the constant-trip loop over a uniform array becomes three
// copies with direct uniform reads (the second and third with fresh
// temporaries: normalize stays an fsqrt_divisor); the loop with a uniform
// bound and the one with a break in its body stay loops.
uniform vec4 lights[3];
uniform int count;

void main() {
    vec3 n = normalize(gl_TexCoord[0].xyz);
    vec4 c = vec4(0.0);
    for (int i = 0; i < 3; ++i)
        c += lights[i] * max(dot(n, normalize(lights[i].xyz)), 0.0);
    for (int i = 0; i < count; ++i)
        c *= 0.5;
    for (int i = 0; i < 4; ++i) {
        if (c.x > 1.0)
            break;
        c.x += 0.25;
    }
    gl_FragColor = c;
}
