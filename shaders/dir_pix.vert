varying vec3 normal, lightDir, ecPos;

void main()
{
    lightDir = normalize(vec3(gl_LightSource[0].position));
    normal = normalize(gl_NormalMatrix * gl_Normal);
    ecPos = vec3(gl_ModelViewMatrix * gl_Vertex) ;
    gl_Position = ftransform();
}
