// The floor's texture, trilinear, faded into fog with the distance.
uniform sampler2D tiles;
varying float depth;

void main()
{
    vec4 t = texture2D(tiles, gl_TexCoord[0].st);
    float fog = clamp((depth - 2.0) / 30.0, 0.0, 1.0);
    gl_FragColor = mix(t, vec4(0.6, 0.65, 0.7, 1.0), fog);
}
