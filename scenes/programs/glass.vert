// Fresnel glass: reflected and refracted rays from the vertex shader (one
// per colour for the dispersion), looked up in a cube map per fragment.
uniform mat3 eye_to_world;
uniform float eta;
uniform float fresnel_power;

varying vec3 reflected;
varying vec3 refracted[3];
varying float fresnel;

void main() {
    vec4 eye_pos = gl_ModelViewMatrix * gl_Vertex;
    vec3 i = normalize(eye_pos.xyz);
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    const vec3 spread = vec3(0.98, 1.0, 1.02);
    reflected = eye_to_world * reflect(i, n);
    for (int c = 0; c < 3; ++c)
        refracted[c] = eye_to_world * refract(i, n, eta * spread[c]);
    float f0 = ((1.0 - eta) * (1.0 - eta)) / ((1.0 + eta) * (1.0 + eta));
    fresnel = f0 + (1.0 - f0) * pow(1.0 - max(dot(-i, n), 0.0), fresnel_power);
    gl_Position = ftransform();
}
