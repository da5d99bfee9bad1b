// A post-processing pass over a rectangle texture (ARB_texture_rectangle):
// the full-window quad carries the texture's texel coordinates, [0, 64] on
// both axes, as an application addresses a window-sized rectangle.
void main(void) {
    gl_TexCoord[0] = vec4(gl_MultiTexCoord0.st * 64.0, 0.0, 1.0);
    gl_Position = ftransform();
}
