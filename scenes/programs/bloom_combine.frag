// The scene plus its glow, with an exposure curve.
uniform sampler2D image;
uniform sampler2D glow;
uniform float glow_strength;
varying vec2 uv;
void main() {
    vec3 c = texture2D(image, uv).rgb + glow_strength * texture2D(glow, uv).rgb;
    gl_FragColor = vec4(1.0 - exp(-c * 1.6), 1.0);
}
