// Rolling hills: a flat grid displaced by a sum of sines in the vertex
// shader (the normal from the analytic derivatives), Gouraud-lit, with the
// eye distance for the fog.
uniform float amplitude;
varying vec3 color;
varying float height;
float terrain(vec2 p) {
    return amplitude * (sin(p.x * 0.35) * cos(p.y * 0.3) + 0.5 * sin(p.x * 0.9 + p.y * 0.7) +
                        0.25 * cos(p.x * 1.7 - p.y * 1.9));
}
void main() {
    vec2 p = gl_Vertex.xy;
    float h = terrain(p);
    float e = 0.05;
    float dx = (terrain(p + vec2(e, 0.0)) - terrain(p - vec2(e, 0.0))) / (2.0 * e);
    float dy = (terrain(p + vec2(0.0, e)) - terrain(p - vec2(0.0, e))) / (2.0 * e);
    vec3 object_normal = normalize(vec3(-dx, -dy, 1.0));   // the grid lies in z = 0, z up
    vec4 vertex = vec4(p, h, 1.0);
    vec3 n = normalize(gl_NormalMatrix * object_normal);
    vec4 eye = gl_ModelViewMatrix * vertex;
    float diffuse = max(dot(n, normalize(gl_LightSource[0].position.xyz)), 0.0);
    color = gl_FrontMaterial.diffuse.rgb * (0.25 + 0.75 * diffuse);
    height = h;
    gl_FogFragCoord = length(eye.xyz);
    gl_Position = gl_ProjectionMatrix * eye;
}
