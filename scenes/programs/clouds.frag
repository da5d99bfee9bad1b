uniform vec3 sky_color;
uniform vec3 cloud_color;
uniform float scale;

varying vec3 model_pos;
varying float light;

// A hash of multiplies and fract only: sin-based hashes amplify each
// implementation's sin error 40000 times.
float hash(vec3 p) {
    p = fract(p * 0.1031);
    p += dot(p, p.yzx + 19.19);
    return fract((p.x + p.y) * p.z);
}

// Trilinear value noise of hashes at the lattice points.
float value_noise(vec3 p) {
    vec3 i = floor(p);
    vec3 f = fract(p);
    f = f * f * (3.0 - 2.0 * f);
    float a = mix(hash(i), hash(i + vec3(1.0, 0.0, 0.0)), f.x);
    float b = mix(hash(i + vec3(0.0, 1.0, 0.0)), hash(i + vec3(1.0, 1.0, 0.0)), f.x);
    float c = mix(hash(i + vec3(0.0, 0.0, 1.0)), hash(i + vec3(1.0, 0.0, 1.0)), f.x);
    float d = mix(hash(i + vec3(0.0, 1.0, 1.0)), hash(i + vec3(1.0, 1.0, 1.0)), f.x);
    return mix(mix(a, b, f.y), mix(c, d, f.y), f.z);
}

void main() {
    vec3 p = model_pos * scale;
    // The built-ins: zero on Mesa and here, so they add nothing but must
    // still compile and run in every form.
    vec4 builtin = noise4(vec4(p, 1.0)) + vec4(noise3(p), 0.0) + vec4(noise2(p.xy), 0.0, 0.0)
                 + vec4(noise1(p.x));
    float sum = 0.0, amplitude = 0.5;
    for (int octave = 0; octave < 4; ++octave) {
        sum += amplitude * (value_noise(p) + builtin[octave]);
        p *= 2.0;
        amplitude *= 0.5;
    }
    float cover = smoothstep(0.45, 0.75, sum);
    gl_FragColor = vec4(mix(sky_color, cloud_color, cover) * light, 1.0);
}
