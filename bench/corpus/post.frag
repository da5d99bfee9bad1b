#version 120
// An ink-and-wash filter over an image: a 3x3 Gaussian blur and a Sobel edge
// detector over the same nine taps, edges drawn dark over the blurred image,
// and a vignette.
uniform sampler2D image;
uniform vec2 texel;          // 1 / the image's size
uniform float edge_strength;
varying vec2 uv;

float luminance(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

void main() {
    const float gauss[9] = float[9](1.0, 2.0, 1.0, 2.0, 4.0, 2.0, 1.0, 2.0, 1.0);
    const float sobel_x[9] = float[9](-1.0, 0.0, 1.0, -2.0, 0.0, 2.0, -1.0, 0.0, 1.0);
    const float sobel_y[9] = float[9](-1.0, -2.0, -1.0, 0.0, 0.0, 0.0, 1.0, 2.0, 1.0);
    vec3 blurred = vec3(0.0);
    float gx = 0.0, gy = 0.0;
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            vec3 c = texture2D(image, uv + vec2(float(i - 1), float(j - 1)) * texel).rgb;
            int k = j * 3 + i;
            blurred += c * gauss[k];
            float y = luminance(c);
            gx += y * sobel_x[k];
            gy += y * sobel_y[k];
        }
    }
    blurred /= 16.0;
    float edge = clamp(length(vec2(gx, gy)) * edge_strength, 0.0, 1.0);
    vec2 centered = uv - 0.5;
    float vignette = 1.0 - dot(centered, centered) * 0.8;
    gl_FragColor = vec4(blurred * (1.0 - edge) * vignette, 1.0);
}
