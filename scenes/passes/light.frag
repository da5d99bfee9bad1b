// Diffuse and specular of light `light` (an index into gl_LightSource), added
// to the framebuffer by the pass's blending.
uniform int light;
varying vec3 normal;
varying vec3 position;
void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[light].position.xyz - position * gl_LightSource[light].position.w);
    vec3 h = normalize(l - normalize(position));
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess) : 0.0;
    gl_FragColor = vec4(gl_FrontMaterial.diffuse.rgb * gl_LightSource[light].diffuse.rgb * diffuse +
                        gl_FrontMaterial.specular.rgb * gl_LightSource[light].specular.rgb * specular, 1.0);
}
