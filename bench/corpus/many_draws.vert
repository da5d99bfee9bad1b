// Many small objects, each drawn with its own colour and phase (one draw
// call and one glUniform pair each), lit per vertex with a rim term.
uniform vec3 tint;
uniform float phase;
varying vec3 color;
void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 position = vec3(gl_ModelViewMatrix * gl_Vertex);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    float diffuse = max(dot(n, l), 0.0);
    float rim = 1.0 - max(dot(n, normalize(-position)), 0.0);
    float pulse = 0.85 + 0.15 * sin(phase);
    color = tint * (0.2 + 0.8 * diffuse) * pulse + vec3(0.3) * rim * rim;
    gl_Position = ftransform();
}
