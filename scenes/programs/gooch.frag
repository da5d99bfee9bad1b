#version 120
uniform vec3 surface_color;
uniform vec3 warm_color;
uniform vec3 cool_color;
uniform float diffuse_warm;
uniform float diffuse_cool;
uniform float hatch_spacing;

varying vec3 normal;
varying vec3 to_light;
varying vec3 to_eye;
varying float diffuse;

// One layer of strokes: 1 on the line, 0 between lines.
float strokes(vec2 p, vec2 dir, float spacing) {
    float d = fract(dot(p, dir) / spacing);
    return step(d, 0.18);
}

void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(to_light);
    vec3 v = normalize(to_eye);
    float ndotl = dot(n, l) * 0.5 + 0.5;
    vec3 cool = min(cool_color + diffuse_cool * surface_color, 1.0);
    vec3 warm = min(warm_color + diffuse_warm * surface_color, 1.0);
    vec3 color = mix(cool, warm, ndotl);
    vec3 r = reflect(-l, n);
    float spec = pow(max(dot(r, v), 0.0), 24.0);
    color = min(color + spec, 1.0);

    // Darker tones get more layers of strokes.
    const vec2 dirs[3] = vec2[3](vec2(0.7071, 0.7071), vec2(0.7071, -0.7071), vec2(1.0, 0.0));
    const float levels[3] = float[](0.55, 0.35, 0.15);
    float ink = 0.0;
    for (int i = 0; i < 3; ++i)
        if (diffuse < levels[i]) ink = max(ink, strokes(gl_FragCoord.xy, dirs[i], hatch_spacing));
    gl_FragColor = vec4(color * (1.0 - 0.6 * ink), 1.0);
}
