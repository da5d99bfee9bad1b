#version 120
// Gradient noise with an arithmetic lattice hash: (2x + 1) x is a
// permutation of the integers modulo 256, and every step stays an integer
// below 2^24, so the hash is exact in fp32 whatever the hardware.
uniform vec3 vein_color, stone_color;
uniform float turbulence_gain;
varying vec3 object_position;
varying vec3 normal, position;

float permute(float x) { return mod((2.0 * x + 1.0) * x + 17.0, 256.0); }

vec3 gradient(vec3 cell) {
    cell = mod(cell, 256.0);
    float h = permute(permute(permute(cell.x) + cell.y) + cell.z);
    // 64 directions from the hash's bits, each component in {-1.5 .. 1.5}
    vec3 g = vec3(mod(h, 4.0), mod(floor(h / 4.0), 4.0), mod(floor(h / 16.0), 4.0)) - 1.5;
    return g;
}

vec3 fade(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

float gradient_noise(vec3 p) {
    vec3 cell = floor(p);
    vec3 f = p - cell;
    vec3 u = fade(f);
    float n000 = dot(gradient(cell), f);
    float n100 = dot(gradient(cell + vec3(1, 0, 0)), f - vec3(1, 0, 0));
    float n010 = dot(gradient(cell + vec3(0, 1, 0)), f - vec3(0, 1, 0));
    float n110 = dot(gradient(cell + vec3(1, 1, 0)), f - vec3(1, 1, 0));
    float n001 = dot(gradient(cell + vec3(0, 0, 1)), f - vec3(0, 0, 1));
    float n101 = dot(gradient(cell + vec3(1, 0, 1)), f - vec3(1, 0, 1));
    float n011 = dot(gradient(cell + vec3(0, 1, 1)), f - vec3(0, 1, 1));
    float n111 = dot(gradient(cell + vec3(1, 1, 1)), f - vec3(1, 1, 1));
    vec4 x = mix(vec4(n000, n010, n001, n011), vec4(n100, n110, n101, n111), u.x);
    vec2 y = mix(x.xz, x.yw, u.y);
    return mix(y.x, y.y, u.z) * 0.4;
}

float turbulence(vec3 p) {
    float sum = 0.0;
    float amplitude = 1.0;
    for (int octave = 0; octave < 4; ++octave) {
        sum += abs(gradient_noise(p)) * amplitude;
        p *= 2.0;
        amplitude *= 0.5;
    }
    return sum;
}

void main() {
    float t = turbulence(object_position);
    float veins = 0.5 + 0.5 * sin(object_position.x * 3.0 + t * turbulence_gain);
    veins = pow(veins, 0.35);
    vec3 albedo = mix(vein_color, stone_color, veins);
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    vec3 h = normalize(l - normalize(position));
    float diffuse = max(dot(n, l), 0.0);
    float specular = pow(max(dot(n, h), 0.0), 48.0);
    gl_FragColor = vec4(albedo * (0.25 + 0.75 * diffuse) + vec3(0.35 * specular), 1.0);
}
