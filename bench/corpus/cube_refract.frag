uniform samplerCube environment;
varying vec3 reflect_dir;
varying vec3 refract_r, refract_g, refract_b;
varying float fresnel;
void main() {
    vec3 reflected = textureCube(environment, reflect_dir).rgb;
    vec3 refracted;
    refracted.r = textureCube(environment, refract_r).r;
    refracted.g = textureCube(environment, refract_g).g;
    refracted.b = textureCube(environment, refract_b).b;
    gl_FragColor = vec4(mix(refracted, reflected, clamp(fresnel, 0.0, 1.0)), 1.0);
}
