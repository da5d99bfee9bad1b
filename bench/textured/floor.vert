// A textured floor seen at a grazing angle, with distance fog in the fragment shader.
varying float depth;

void main()
{
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    depth = -(gl_ModelViewMatrix * gl_Vertex).z;
    gl_Position = ftransform();
}
