#version 120
// Shaded particles: the size attenuated from gl_Point as GL's fixed function
// would (GL applies none to a vertex shader's points), a fade with height.
void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    float d = length(eye.xyz);
    float att = gl_Point.distanceConstantAttenuation + d * (gl_Point.distanceLinearAttenuation
              + d * gl_Point.distanceQuadraticAttenuation);
    gl_PointSize = clamp(gl_Point.size * inversesqrt(att), gl_Point.sizeMin, gl_Point.sizeMax);
    gl_FrontColor = gl_Color;
    gl_Position = ftransform();
}
