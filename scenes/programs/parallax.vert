// Parallax (offset) mapping on a floor and a wall: tangent space from the
// normal matrix and a per-object tangent, the eye and light vectors carried
// into it for the fragment shader.
uniform vec3 tangent;

varying vec3 eye_ts;
varying vec3 light_ts;
varying vec2 uv;

void main() {
    vec4 eye_pos = gl_ModelViewMatrix * gl_Vertex;
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 t = normalize(gl_NormalMatrix * tangent);
    vec3 b = cross(n, t);
    mat3 to_tangent = mat3(t.x, b.x, n.x, t.y, b.y, n.y, t.z, b.z, n.z);
    eye_ts = to_tangent * -eye_pos.xyz;
    light_ts = to_tangent * (gl_LightSource[0].position.xyz - eye_pos.xyz);
    uv = (gl_TextureMatrix[0] * gl_MultiTexCoord0).st;
    gl_Position = ftransform();
}
