#version 400 compatibility
// The lecture's per-pixel directional light (dir_pix.vert) with a texture:
// the texture coordinates go through the texture matrix, as fixed function
// would transform them.
varying vec3 normal, lightDir, ecPos;

void main()
{
    lightDir = normalize(vec3(gl_LightSource[0].position));
    normal = normalize(gl_NormalMatrix * gl_Normal);
    ecPos = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_Position = ftransform();
}
