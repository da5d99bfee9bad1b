#version 120
// A 7-tap Gaussian along one axis, weights in a const array; the taps
// between texels use linear filtering.
uniform sampler2D image;
uniform vec2 step;
varying vec2 uv;
const float kWeight[4] = float[4](0.2270, 0.1945, 0.1216, 0.0540);
void main() {
    vec4 sum = texture2D(image, uv) * kWeight[0];
    for (int i = 1; i < 4; ++i) {
        sum += texture2D(image, uv + step * float(i)) * kWeight[i];
        sum += texture2D(image, uv - step * float(i)) * kWeight[i];
    }
    gl_FragColor = vec4(sum.rgb, 1.0);
}
