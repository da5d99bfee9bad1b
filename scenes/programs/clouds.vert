// Clouds on a sky dome and a marble sphere from the built-in noise
// functions (the Orange Book's noise chapter), with a hashed value noise as
// the fall-back that most drivers' zero-returning noise made programs carry.
varying vec3 model_pos;
varying float light;
void main() {
    model_pos = gl_Vertex.xyz;
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    light = 0.4 + 0.6 * max(dot(n, normalize(gl_LightSource[0].position.xyz)), 0.0);
    gl_Position = ftransform();
}
