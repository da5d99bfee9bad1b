void main(){

    vec3 normal,lightDir;
    vec4 diffuse,ambient;
    float intensity;

    lightDir = normalize(vec3(gl_LightSource[0].position));
    normal = normalize(gl_NormalMatrix * gl_Normal);

    intensity = max(dot(lightDir,normal),0.0);
    diffuse = gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse;
    ambient = gl_LightSource[0].ambient * gl_FrontMaterial.ambient;

    gl_FrontColor = ambient + diffuse*intensity;
    gl_FrontColor += gl_FrontMaterial.ambient * gl_LightModel.ambient;
    gl_FrontColor += gl_FrontMaterial.emissive;
    gl_Position = ftransform();
}
