// An edge-enhancing 3x3 filter of a rectangle texture in texel units, the
// image darkened towards the border; sampler2DRect needs no #extension line,
// as in Mesa and NVIDIA's drivers.
uniform sampler2DRect image;

void main(void) {
    vec2 p = gl_TexCoord[0].st;
    vec4 sum = vec4(0.0);
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            sum += texture2DRect(image, p + vec2(float(i), float(j)));
    vec4 center = texture2DRect(image, p);
    vec4 sharpened = center + 0.5 * (center - sum / 9.0);
    float vignette = 1.0 - 0.4 * length(p / 64.0 - 0.5);
    gl_FragColor = vec4(clamp(sharpened.rgb * vignette, 0.0, 1.0), 1.0);
}
