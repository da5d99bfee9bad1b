varying vec3 normal, ecPos;

void main()
{
    vec4 diffuse, ambient, specular, color;
    float intensity, shininess, d, att;
    vec3 n, hv, ec , lightDir;

    lightDir = vec3(gl_LightSource[0].position)-ecPos;
    n = normalize(normal);

    d = length(lightDir);
    att = max(1.0, 1.0 / (gl_LightSource[0].constantAttenuation +
                        gl_LightSource[0].linearAttenuation * d +
                        gl_LightSource[0].quadraticAttenuation * d * d));

    diffuse = gl_LightSource[0].diffuse * FrontMaterial.diffuse;
    ambient = gl_LightSource[0].ambient * gl_FrontMaterial.ambient;

    lightDir = normalize(lightDir)
    intensity = max(dot(lightDir, n), 0.0);
    color = (ambient + diffuse*intensity) * att;
    color += gl_FrontMaterial.ambient * gl_LightModel.ambient;
    color += gl_FrontMaterial.emission;

    if (intensity > 0.0) {
        ec = normalize(-ecPos);
        hv = normalize(ec+lightDir);
        shininess = pow(max(dot(hv,n),0.0),gl_FrontMaterial.shininess);
        specular = shininess * gl_LightSource[0].specular * gl_FrontMaterial.specular;
        color += specular * att;
    }

    gl_FragColor = color;
}
