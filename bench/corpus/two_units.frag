uniform sampler2D base_map;
uniform sampler2D decal_map;
varying float diffuse;
void main() {
    vec4 base = texture2D(base_map, gl_TexCoord[0].st);
    vec4 decal = texture2D(decal_map, gl_TexCoord[1].st);
    vec3 color = mix(base.rgb, decal.rgb, decal.a);   // the decal over the base, by its alpha
    gl_FragColor = vec4(color * (0.3 + 0.7 * diffuse), 1.0);
}
