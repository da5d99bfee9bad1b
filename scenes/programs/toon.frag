#version 120
varying vec3 normal;
varying vec3 position;

const int kBands = 4;
const float kThreshold[kBands] = float[kBands](0.95, 0.5, 0.25, 0.0);
const float kShade[kBands] = float[kBands](1.0, 0.7, 0.45, 0.25);

float band(float intensity) {
    for (int i = 0; i < kBands; i++)
        if (intensity > kThreshold[i]) return kShade[i];
    return 0.1;
}

void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - position);
    float shade = band(dot(n, l));
    vec3 h = normalize(l + normalize(-position));
    float highlight = step(0.97, dot(n, h));
    vec4 base = gl_FrontMaterial.diffuse * shade + gl_FrontMaterial.ambient * gl_LightModel.ambient;
    gl_FragColor = vec4(mix(base.rgb, vec3(1.0), highlight), 1.0);
}
