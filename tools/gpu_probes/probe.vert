#version 110
// The probes' full-screen quad (the quad mesh has corners at +-1): no matrices.
void main() { gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0); }
