uniform sampler2D leaves;
uniform bool textured;
void main() {
    vec4 texel = textured ? texture2D(leaves, gl_TexCoord[0].st) : vec4(1.0);
    gl_FragColor = gl_Color * texel;
}
