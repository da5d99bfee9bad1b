// A full-screen quad's texture coordinates for raytrace.frag.
#version 120
varying vec2 uv;
void main() {
    uv = gl_MultiTexCoord0.xy;
    gl_Position = ftransform();
}
