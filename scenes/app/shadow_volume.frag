// lit = 0: the ambient pass; lit = 1: the light's diffuse term alone, added
// where the stencil says the pixel is outside every shadow volume.
uniform float lit;
varying vec3 normal;
varying vec3 to_light;
void main() {
    vec3 n = normalize(normal);
    float d = max(dot(n, normalize(to_light)), 0.0);
    vec3 ambient = gl_Color.rgb * gl_LightModel.ambient.rgb;
    vec3 diffuse = gl_Color.rgb * gl_LightSource[0].diffuse.rgb * d;
    gl_FragColor = vec4(mix(ambient, diffuse, lit), 1.0);
}
