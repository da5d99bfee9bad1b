void main()
{
    vec3 normal = normalize(gl_NormalMatrix * gl_Normal);
    vec3 lightDir = normalize(vec3(gl_LightSource[0].position));
    float intensity = max(dot(lightDir, normal), 0.0);
    gl_FrontColor = intensity * gl_FrontMaterial.diffuse * gl_LightSource[0].diffuse;
    gl_Position = ftransform();
}
