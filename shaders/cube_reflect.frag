// Environment mapping, per pixel: the view direction reflected about the
// normal looks up a cube map, shaded by a directional light. The reflection
// is in eye space; a camera that only translates (the lecture's) makes that
// the cube map's world space.
uniform samplerCube env;
varying vec3 normal, ecPos;

void main()
{
    vec3 n = normalize(normal);
    vec3 r = reflect(normalize(ecPos), n);
    vec3 l = normalize(vec3(gl_LightSource[0].position));
    float intensity = max(dot(n, l), 0.0);
    gl_FragColor = textureCube(env, r) * (0.4 + 0.6 * intensity);
}
