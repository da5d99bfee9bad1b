// Antialiased procedural brick (the Orange Book's analytic box filter via
// fwidth), with the lighting in the vertex shader as the book's brick did.
uniform vec3 light_position;
varying vec2 mc_position;
varying float intensity;
void main() {
    vec3 p = vec3(gl_ModelViewMatrix * gl_Vertex);
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 l = normalize(light_position - p);
    vec3 r = reflect(-l, n);
    float spec = max(dot(r, normalize(-p)), 0.0);
    spec = pow(spec, 16.0);
    intensity = 0.7 * max(dot(l, n), 0.0) + 0.3 * spec;
    mc_position = gl_Vertex.xy;
    gl_Position = ftransform();
}
