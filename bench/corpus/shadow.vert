// Shadow mapping: the world position through the light's matrix (bias *
// light projection * light view) gives the shadow-map coordinates; the
// fragment shader compares with shadow2DProj, four taps (percentage-closer
// filtering by hand, as ShaderX-era demos did on hardware without it).
uniform mat4 model;          // the object's model matrix
uniform mat4 light_matrix;   // world -> shadow map
varying vec4 shadow_coord;
varying vec3 normal, position;
void main() {
    vec4 world = model * gl_Vertex;
    shadow_coord = light_matrix * world;
    position = vec3(gl_ModelViewMatrix * gl_Vertex);
    normal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
