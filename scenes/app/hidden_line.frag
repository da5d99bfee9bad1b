uniform sampler2D decal;
uniform bool textured;
// paint.a > 0: the hidden-line fill, in the background's colour.
uniform vec4 paint;
void main() {
    vec4 c = textured ? gl_Color * texture2D(decal, gl_TexCoord[0].st) : gl_Color;
    gl_FragColor = paint.a > 0.0 ? vec4(paint.rgb, 1.0) : c;
}
