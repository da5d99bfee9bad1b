// Value noise: a pseudo-random value per lattice point, interpolated with a
// cubic. The lattice hash uses only integer products below 2^24 and
// divisions by powers of two, exact in fp32.
uniform float ring_scale;
uniform vec3 light_wood, dark_wood;
varying vec3 object_position;
varying vec3 normal, position;

float lattice(vec3 c) {
    c = mod(c, 128.0);
    float h = mod(c.x * 97.0 + c.y * 59.0 + c.z * 31.0, 128.0);
    h = mod(h * h * 3.0 + h * 7.0 + 5.0, 1024.0);
    return h / 1024.0;
}

float value_noise(vec3 p) {
    vec3 c = floor(p);
    vec3 f = p - c;
    f = f * f * (3.0 - 2.0 * f);
    float a = mix(lattice(c), lattice(c + vec3(1.0, 0.0, 0.0)), f.x);
    float b = mix(lattice(c + vec3(0.0, 1.0, 0.0)), lattice(c + vec3(1.0, 1.0, 0.0)), f.x);
    float d = mix(lattice(c + vec3(0.0, 0.0, 1.0)), lattice(c + vec3(1.0, 0.0, 1.0)), f.x);
    float e = mix(lattice(c + vec3(0.0, 1.0, 1.0)), lattice(c + vec3(1.0, 1.0, 1.0)), f.x);
    return mix(mix(a, b, f.y), mix(d, e, f.y), f.z);
}

void main() {
    vec3 p = object_position;
    float wobble = value_noise(p * 3.0) * 0.6 + value_noise(p * 7.0) * 0.25;
    float r = length(p.xz) * ring_scale + wobble;
    float ring = fract(r);
    // a profile that is continuous where fract wraps: early wood, late wood
    float profile = smoothstep(0.0, 0.7, ring) * (1.0 - smoothstep(0.85, 1.0, ring));
    float grain = value_noise(vec3(p.x * 40.0, p.y * 2.0, p.z * 40.0)) * 0.15;
    vec3 albedo = mix(light_wood, dark_wood, clamp(profile + grain, 0.0, 1.0));
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - position);
    vec3 h = normalize(l - normalize(position));
    float diffuse = max(dot(n, l), 0.0);
    float specular = pow(max(dot(n, h), 0.0), 24.0) * 0.25;
    gl_FragColor = vec4(albedo * (0.3 + 0.7 * diffuse) + vec3(specular), 1.0);
}
