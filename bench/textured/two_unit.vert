// Two texture units on one full-screen quad: the second unit's texture
// coordinates are the first's, scaled by its own texture matrix.
void main()
{
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_TexCoord[1] = gl_TextureMatrix[1] * gl_MultiTexCoord0;
    gl_Position = ftransform();
}
