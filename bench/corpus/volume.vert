// Volume rendering by slices: each slice is a quad through a 3D texture at
// depth slice_r, drawn back to front and blended "over".
uniform float slice_r;
varying vec3 stp;
void main() {
    stp = vec3(gl_Vertex.xy * 0.5 + 0.5, slice_r);
    gl_Position = ftransform();
}
