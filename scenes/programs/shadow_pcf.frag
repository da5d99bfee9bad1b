#version 120
// 3x3 percentage-closer filtering through shadow2D, each tap itself
// bilinearly filtered by the sampler (GL_LINEAR on a compared depth texture).
uniform sampler2DShadow shadow_map;
uniform float texel;

varying vec3 normal;
varying vec3 position;
varying vec4 shadow_coord;

const vec2 kTaps[9] = vec2[9](vec2(-1.0, -1.0), vec2(0.0, -1.0), vec2(1.0, -1.0),
                              vec2(-1.0, 0.0), vec2(0.0, 0.0), vec2(1.0, 0.0),
                              vec2(-1.0, 1.0), vec2(0.0, 1.0), vec2(1.0, 1.0));

float visibility(vec4 coord) {
    if (coord.w <= 0.0) return 1.0;
    vec3 p = coord.xyz / coord.w;
    float sum = 0.0;
    for (int i = 0; i < 9; ++i)
        sum += shadow2D(shadow_map, p + vec3(kTaps[i] * texel, 0.0)).r;
    return sum / 9.0;
}

void main() {
    vec3 n = normalize(normal);
    vec3 l = gl_LightSource[0].position.xyz - position;
    float d = length(l);
    l /= d;
    float spot = dot(-l, normalize(gl_LightSource[0].spotDirection));
    float cone = smoothstep(gl_LightSource[0].spotCosCutoff, gl_LightSource[0].spotCosCutoff + 0.05, spot);
    float attenuation = 1.0 / (gl_LightSource[0].constantAttenuation + gl_LightSource[0].linearAttenuation * d);
    float diffuse = max(dot(n, l), 0.0) * cone * attenuation * visibility(shadow_coord);
    vec4 color = gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[0].diffuse * diffuse;
    gl_FragColor = vec4(color.rgb, 1.0);
}
