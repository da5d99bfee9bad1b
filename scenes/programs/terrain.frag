#version 120
centroid varying vec3 normal;
varying vec3 position;
varying float height;

const vec3 kColors[4] = vec3[](vec3(0.1, 0.3, 0.7), vec3(0.8, 0.75, 0.5), vec3(0.25, 0.55, 0.2), vec3(0.95));
const float kLevels[4] = float[](0.0, 0.2, 0.35, 0.7);

vec3 ramp(float h) {
    vec3 c = kColors[0];
    for (int i = 1; i < kColors.length(); ++i)
        c = mix(c, kColors[i], smoothstep(kLevels[i] - 0.05, kLevels[i] + 0.05, h));
    return c;
}

void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    float diffuse = max(dot(n, l), 0.0);
    vec3 c = ramp(height) * (gl_LightModel.ambient.rgb + diffuse * gl_LightSource[0].diffuse.rgb);
    float fog = clamp((gl_Fog.end + position.z) * gl_Fog.scale, 0.0, 1.0);
    gl_FragColor = vec4(mix(gl_Fog.color.rgb, c, fog), 1.0);
}
