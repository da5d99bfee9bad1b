void main() {

    vec3 normal, lightDir;
    vec4 diffuse, ambient, specular;
    float intensity, shininess, aux;

    lightDir = normalize(vec3(gl_LightSource[0].position));
    normal = normalize(gl_NormalMatrix * gl_Normal);

    intensity = max(dot(lightDir, normal), 0.0);
    diffuse = gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse;
    ambient = gl_LightSource[0].ambient * gl_FrontMaterial.ambient;

    gl_FrontColor = ambient + diffuse*intensity;
    gl_FrontColor += gl_FrontMaterial.ambient * gl_LightModel.ambient;
    gl_FrontColor += gl_FrontMaterial.emission;

    if (intensity > 0.0) {
        aux = max(dot(vec3(gl_LightSource[0].halfVector), normal), 0.0);
        shininess = pow(aux, gl_FrontMaterial.shininess);
        specular = gl_LightSource[0].specular * gl_FrontMaterial.specular;
        specular *= shininess;
        gl_FrontColor += specular;
    }
    gl_Position = ftransform();
}
