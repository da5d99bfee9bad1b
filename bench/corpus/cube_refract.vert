// Glass: reflection and refraction of an environment cube map, mixed by
// Schlick's approximation of the Fresnel term, with a slight dispersion (one
// refraction ratio per colour channel). World-space vectors come from the
// model matrix, a uniform, as in most demos of the time.
uniform mat4 model;
uniform vec3 eye_position;   // world space
const float eta = 0.66;      // air to glass
const vec3 eta_rgb = vec3(0.65, 0.66, 0.67);
varying vec3 reflect_dir;
varying vec3 refract_r, refract_g, refract_b;
varying float fresnel;
void main() {
    vec3 world = vec3(model * gl_Vertex);
    vec3 n = normalize(mat3(model[0].xyz, model[1].xyz, model[2].xyz) * gl_Normal);
    vec3 i = normalize(world - eye_position);
    reflect_dir = reflect(i, n);
    refract_r = refract(i, n, eta_rgb.r);
    refract_g = refract(i, n, eta_rgb.g);
    refract_b = refract(i, n, eta_rgb.b);
    float f0 = ((1.0 - eta) * (1.0 - eta)) / ((1.0 + eta) * (1.0 + eta));
    fresnel = f0 + (1.0 - f0) * pow(1.0 - max(dot(-i, n), 0.0), 5.0);
    gl_Position = ftransform();
}
