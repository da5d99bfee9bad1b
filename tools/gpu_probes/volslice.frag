#version 110
// bench/corpus/volume.frag's lookup on one slice, unblended: channel `chan` (0 red, 1 green,
// 2 blue) of texture3D(volume, stp * 1.5) as e = floor(v * 65536 + 1/2) mod 65536 in four nibbles.
uniform sampler3D volume;
uniform float chan;
varying vec3 stp;
vec4 enc(float v) {
    float e = floor(v * 65536.0 + 0.5);
    e = e - 65536.0 * floor(e / 65536.0);
    float n3 = floor(e / 4096.0);
    float n2 = floor(e / 256.0) - 16.0 * n3;
    float n1 = floor(e / 16.0) - 16.0 * floor(e / 256.0);
    float n0 = e - 16.0 * floor(e / 16.0);
    return vec4(n3, n2, n1, n0) * (17.0 / 255.0);
}
void main() {
    vec3 c = texture3D(volume, stp * 1.5).rgb;
    gl_FragColor = enc(chan < 0.5 ? c.r : chan < 1.5 ? c.g : c.b);
}
