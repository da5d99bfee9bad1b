uniform sampler2D normal_map;
uniform sampler2D color_map;
varying vec3 light_tangent, view_tangent;
varying vec2 uv;
void main() {
    vec3 n = normalize(texture2D(normal_map, uv).xyz * 2.0 - 1.0);
    vec3 l = normalize(light_tangent);
    vec3 v = normalize(view_tangent);
    vec3 h = normalize(l + v);
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess) : 0.0;
    vec3 albedo = texture2D(color_map, uv * 0.25).rgb;
    vec3 color = albedo * (gl_LightModel.ambient.rgb + gl_LightSource[0].diffuse.rgb * diffuse) +
                 gl_FrontMaterial.specular.rgb * gl_LightSource[0].specular.rgb * specular;
    gl_FragColor = vec4(color, 1.0);
}
