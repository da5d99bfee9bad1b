#version 120
// Particles sized as GL's point parameters say (glPointParameter, read
// through gl_Point): size / sqrt(a + b d + c d^2), d the distance from the
// eye, clamped to [sizeMin, sizeMax]. Below the fade threshold a particle
// keeps the threshold's size and fades with the square of the ratio (GL 2.1
// §3.3's rule, which GL itself applies only with multisampling). Its age,
// 0 to 1, shrinks and dims it.
attribute float age;

void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    float d = length(eye.xyz);
    float attenuation = inversesqrt(gl_Point.distanceConstantAttenuation +
                                    d * (gl_Point.distanceLinearAttenuation + d * gl_Point.distanceQuadraticAttenuation));
    float size = clamp(gl_Point.size * (1.0 - 0.6 * age) * attenuation, gl_Point.sizeMin, gl_Point.sizeMax);
    float ratio = min(size / gl_Point.fadeThresholdSize, 1.0);
    gl_PointSize = max(size, gl_Point.fadeThresholdSize);
    gl_FrontColor = vec4(gl_Color.rgb, gl_Color.a * (1.0 - 0.7 * age) * ratio * ratio);
    gl_TexCoord[0] = vec4(0.0);  // a sprite's, with GL_COORD_REPLACE on unit 0
    gl_Position = gl_ProjectionMatrix * eye;
}
