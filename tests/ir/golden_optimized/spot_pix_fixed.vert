varying vec3 normal, ecPos;

void main()
{

    normal = normalize(gl_NormalMatrix * gl_Normal);
    ecPos = vec3(gl_ModelViewMatrix * gl_Vertex) ;

    gl_Position = ftransform();
}
