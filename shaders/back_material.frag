// Per-pixel directional light with the material of the visible side: back
// faces use gl_BackMaterial, gl_BackLightProduct and the reversed normal.
varying vec3 normal, ecPos;

void main()
{
    vec3 n = normalize(gl_FrontFacing ? normal : -normal);
    vec3 l = normalize(vec3(gl_LightSource[0].position));
    vec3 h = normalize(l + normalize(-ecPos));
    float intensity = max(dot(l, n), 0.0);
    float spec = intensity > 0.0 ? pow(max(dot(h, n), 0.0), gl_FrontFacing ? gl_FrontMaterial.shininess
                                                                              : gl_BackMaterial.shininess) : 0.0;
    if (gl_FrontFacing)
        gl_FragColor = gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[0].ambient
                     + gl_FrontLightProduct[0].diffuse * intensity + gl_FrontLightProduct[0].specular * spec;
    else
        gl_FragColor = gl_BackLightModelProduct.sceneColor + gl_BackLightProduct[0].ambient
                     + gl_BackLightProduct[0].diffuse * intensity + gl_BackLightProduct[0].specular * spec;
}
