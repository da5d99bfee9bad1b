// One direction of a 5-tap binomial blur (1 4 6 4 1) / 16.
uniform sampler2D image;
uniform vec2 step;  // one texel along the blur's direction
void main() {
    vec2 t = gl_TexCoord[0].st;
    vec4 c = 6.0 * texture2D(image, t);
    c += 4.0 * (texture2D(image, t - step) + texture2D(image, t + step));
    c += texture2D(image, t - 2.0 * step) + texture2D(image, t + 2.0 * step);
    gl_FragColor = c / 16.0;
}
