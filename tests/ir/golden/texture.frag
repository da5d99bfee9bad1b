// texture lookups: projection, bias, shadow reference, derivatives
uniform sampler2D tex;
uniform sampler2DShadow depth;

void main() {
    vec4 a = texture2DProj(tex, gl_TexCoord[0], 0.5);
    vec4 b = shadow2D(depth, gl_TexCoord[0].xyz);
    gl_FragColor = a * b.r;
}
