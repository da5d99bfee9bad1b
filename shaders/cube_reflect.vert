// Environment mapping (with cube_reflect.frag): the eye-space normal and
// position, for a per-pixel reflection vector.
varying vec3 normal, ecPos;

void main()
{
    normal = gl_NormalMatrix * gl_Normal;
    ecPos = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_Position = ftransform();
}
