uniform samplerCube environment;

varying vec3 reflected;
varying vec3 refracted[3];
varying float fresnel;

void main() {
    vec3 refraction;
    refraction.r = textureCube(environment, refracted[0]).r;
    refraction.g = textureCube(environment, refracted[1]).g;
    refraction.b = textureCube(environment, refracted[2]).b;
    vec3 reflection = textureCube(environment, reflected).rgb;
    gl_FragColor = vec4(mix(refraction, reflection, clamp(fresnel, 0.0, 1.0)), 1.0);
}
