// Procedural bricks, lit per vertex (the classic two-stage split: the vertex
// shader computes a light intensity, the fragment shader the pattern from
// the object-space position).
uniform vec3 light_position;   // eye space
const float specular_part = 0.3;
const float diffuse_part = 1.0 - specular_part;
varying float intensity;
varying vec2 pattern_position;

void main() {
    vec3 position = vec3(gl_ModelViewMatrix * gl_Vertex);
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 to_light = normalize(light_position - position);
    vec3 reflected = reflect(-to_light, n);
    vec3 to_eye = normalize(-position);
    float diffuse = max(dot(to_light, n), 0.0);
    float spec = 0.0;
    if (diffuse > 0.0) {
        spec = max(dot(reflected, to_eye), 0.0);
        spec = pow(spec, 16.0);
    }
    intensity = diffuse_part * diffuse + specular_part * spec;
    pattern_position = gl_Vertex.xy;
    gl_Position = ftransform();
}
