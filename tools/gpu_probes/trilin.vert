#version 400 compatibility
// trilin.frag's full-screen quad (the quad mesh has corners at +-1), in GLSL 4.00 as the fragment shader.
void main() { gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0); }
