// Normal mapping on a torus: the light and view vectors in tangent space.
// The torus (z its axis) gives no tangent attribute, so the tangent is the
// direction around the axis, from the position; the bitangent completes it.
varying vec3 light_tangent, view_tangent;
varying vec2 uv;
void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 t = normalize(gl_NormalMatrix * vec3(-gl_Vertex.y, gl_Vertex.x, 0.0));
    t = normalize(t - n * dot(n, t));
    vec3 b = cross(n, t);
    vec3 position = vec3(gl_ModelViewMatrix * gl_Vertex);
    vec3 l = gl_LightSource[0].position.xyz - position;
    vec3 v = -position;
    light_tangent = vec3(dot(l, t), dot(l, b), dot(l, n));
    view_tangent = vec3(dot(v, t), dot(v, b), dot(v, n));
    uv = (gl_TextureMatrix[0] * gl_MultiTexCoord0).st;
    gl_Position = ftransform();
}
