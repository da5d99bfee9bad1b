// Bright pass over HDR colours: only what exceeds the threshold (above 1,
// which no fixed-point target could hold) goes on to the blur.
uniform sampler2D image;
uniform float threshold;
varying vec2 uv;
void main() {
    vec3 c = texture2D(image, uv).rgb;
    gl_FragColor = vec4(max(c - vec3(threshold), 0.0), 1.0);
}
