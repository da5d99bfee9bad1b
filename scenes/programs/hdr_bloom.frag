// The lit scene in high dynamic range: a light several times brighter than
// 1, so the highlights and the lamp go well past what GL_RGBA8 could keep.
uniform float intensity;
varying vec3 normal;
varying vec3 position;
void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - position);
    vec3 h = normalize(l - normalize(position));
    float diffuse = max(dot(n, l), 0.0);
    float spec = pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess);
    vec4 c = gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[0].diffuse * diffuse
           + gl_FrontLightProduct[0].specular * spec;
    gl_FragColor = vec4(c.rgb * intensity, 1.0);
}
