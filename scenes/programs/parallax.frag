uniform sampler2D height_map;
uniform sampler2D color_map;
uniform vec2 scale_bias;

varying vec3 eye_ts;
varying vec3 light_ts;
varying vec2 uv;

// Three steps of iterated offset mapping, each refining the height under
// the shifted coordinate.
vec2 parallax(vec2 st, vec3 v) {
    for (int i = 0; i < 3; ++i) {
        float h = texture2D(height_map, st).r * scale_bias.x - scale_bias.y;
        st += h * v.xy / v.z / 3.0;
    }
    return st;
}

void main() {
    vec3 v = normalize(eye_ts);
    vec2 st = parallax(uv, v);
    // The normal from the height map's differences, as the demos built it.
    const vec2 d = vec2(1.0 / 64.0, 0.0);
    float hx = texture2D(height_map, st + d.xy).r - texture2D(height_map, st - d.xy).r;
    float hy = texture2D(height_map, st + d.yx).r - texture2D(height_map, st - d.yx).r;
    vec3 n = normalize(vec3(-hx * 2.0, -hy * 2.0, 1.0));
    vec3 l = normalize(light_ts);
    vec3 h = normalize(l + v);
    vec4 base = texture2D(color_map, st);
    float diffuse = max(dot(n, l), 0.0);
    float spec = pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess);
    gl_FragColor = base * (gl_LightModel.ambient + gl_LightSource[0].diffuse * diffuse)
                 + gl_LightSource[0].specular * gl_FrontMaterial.specular * spec;
}
