// The slides' parts (1), (2) and (3), joined.
varying vec3 normal, lightDir, ecPos;

void main()
{
    vec4 diffuse, ambient, specular, color;
    float intensity, shininess;
    vec3 n, hv, ec;

    n = normalize(normal);
    intensity = max(dot(lightDir, n), 0.0);

    diffuse = gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse;
    ambient = gl_LightSource[0].ambient * gl_FrontMaterial.ambient;

    color = ambient + diffuse*intensity;
    color += gl_FrontMaterial.ambient * gl_LightModel.ambient;
    color += gl_FrontMaterial.emission;

    if (intensity > 0.0) {
        ec = normalize(-ecPos);
        hv = normalize(ec+lightDir);
        shininess = pow(max(dot(hv,n),0.0),gl_FrontMaterial.shininess);
        specular = shininess * gl_LightSource[0].specular * gl_FrontMaterial.specular;
        color += specular;
    }

    gl_FragColor = color;
}
