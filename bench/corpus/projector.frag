uniform sampler2D slide;
varying vec4 projector_coord;
varying vec3 normal, position;
void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - position);
    float diffuse = max(dot(n, l), 0.0);
    vec3 projected = vec3(0.0);
    if (projector_coord.q > 0.0)   // only in front of the projector
        projected = texture2DProj(slide, projector_coord).rgb;
    vec3 base = gl_FrontMaterial.diffuse.rgb;
    gl_FragColor = vec4(base * (gl_LightModel.ambient.rgb + diffuse * projected), 1.0);
}
