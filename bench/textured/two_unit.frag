// A detail texture mixed into a base texture by the detail's alpha, then
// tinted by the vertex colour: the multitexture idiom of GL 1.3-era demos.
uniform sampler2D base, detail;

void main()
{
    vec4 b = texture2D(base, gl_TexCoord[0].st);
    vec4 d = texture2D(detail, gl_TexCoord[1].st);
    gl_FragColor = vec4(mix(b.rgb, d.rgb, d.a), 1.0) * (0.5 + 0.5 * gl_Color);
}
