uniform float alpha;
varying vec3 normal, position;
void main() {
    vec3 n = normalize(gl_FrontFacing ? normal : -normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - position * gl_LightSource[0].position.w);
    vec3 h = normalize(l - normalize(position));
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess) : 0.0;
    vec3 color = gl_FrontMaterial.ambient.rgb * gl_LightModel.ambient.rgb +
                 gl_FrontMaterial.diffuse.rgb * diffuse + gl_FrontMaterial.specular.rgb * specular;
    gl_FragColor = vec4(color, alpha);
}
