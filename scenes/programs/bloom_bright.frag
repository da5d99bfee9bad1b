// Bright pass: what exceeds the threshold in luminance, scaled back.
uniform sampler2D image;
uniform float threshold;
varying vec2 uv;
void main() {
    vec3 c = texture2D(image, uv).rgb;
    float luma = dot(c, vec3(0.299, 0.587, 0.114));
    gl_FragColor = vec4(c * max(luma - threshold, 0.0) / max(luma, 0.0001), 1.0);
}
