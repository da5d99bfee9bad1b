// Reads each band back onto the RGBA8 output as bytes that tell the
// rounding rules apart (0, 1/4, 1/2, 1); the last band's left half shows
// the cleared target, its right half the uploaded texture.
uniform sampler2D image;
uniform sampler2D cleared;
uniform sampler2D data;
float big(float v) { return v == 65504.0 ? 1.0 : (v > 65504.0 ? 0.5 : 0.25); }
vec4 tie_bits(vec4 c) {
    return vec4((c.r - 1.0) * 1024.0, (c.g - 1.0) * 512.0, c.b * 16777216.0 / 4.0, big(c.a));
}
void main() {
    vec4 t = texture2D(image, gl_TexCoord[0].st);
    float i = floor(gl_FragCoord.x);
    float band = floor(gl_FragCoord.y / 8.0);
    vec4 o = vec4(0.0, 0.0, 0.0, 1.0);
    if (band < 2.0) o = vec4((t.r - 1.0) * 1024.0 - i, 0.5, band * 0.5, 1.0);
    else if (band < 3.0) o = vec4(big(t.r), big(t.g), big(-t.b), 1.0);
    else if (band < 4.0) o = vec4(t.r * 16777216.0 - i, t.r * 16777216.0 / 64.0, 0.0, 1.0);
    else if (band < 5.0) o = t * 0.25 + 0.5;
    else if (band < 6.0) o = vec4((-t.r - 1.0) * 1024.0 - i, 0.0, 0.5, 1.0);
    else if (band < 7.0) o = vec4((t.r - 1.0) * 1024.0 - i, (t.g - 1.0) * 1024.0 - i, big(t.b), 1.0);
    else if (gl_FragCoord.x < 32.0) o = tie_bits(texture2D(cleared, vec2(0.5)));
    else o = tie_bits(texture2D(data, vec2(0.5)));
    gl_FragColor = o;
}
