uniform sampler1D ramp;
uniform vec3 base_color;
varying vec3 normal, position;
void main() {
    vec3 n = normalize(normal);
    vec3 v = normalize(-position);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    float intensity = max(dot(n, l), 0.0);
    vec3 band = texture1D(ramp, intensity * 0.999).rgb;
    float spot = step(0.97, max(dot(n, normalize(l + v)), 0.0));
    float outline = step(0.25, dot(n, v));
    vec3 color = (base_color * band + vec3(spot * 0.6)) * outline;
    gl_FragColor = vec4(color, 1.0);
}
