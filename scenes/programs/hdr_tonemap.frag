// Exposure, the glow added, Reinhard's operator and a display gamma: the
// only pass that writes to the RGBA8 output.
uniform sampler2D image;
uniform sampler2D glow;
uniform float exposure;
varying vec2 uv;
void main() {
    vec3 c = (texture2D(image, uv).rgb + texture2D(glow, uv).rgb) * exposure;
    c = c / (1.0 + c);
    gl_FragColor = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
