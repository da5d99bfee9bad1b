// Shell fur (Lengyel's shells, as the NVIDIA and ATI fur demos drew them):
// the mesh drawn again and again, each shell pushed out along the normal
// and sagging under gravity, the hair's density read per fragment.
uniform float shell;        // 0 at the skin, 1 at the tips
uniform float fur_length;
uniform vec3 gravity;       // object space

varying vec2 st;
varying float lit;

void main() {
    vec3 n = normalize(gl_Normal);
    vec3 p = gl_Vertex.xyz + n * fur_length * shell + gravity * shell * shell;
    vec3 eye_n = normalize(gl_NormalMatrix * n);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    lit = 0.35 + 0.65 * max(dot(eye_n, l), 0.0);
    st = gl_MultiTexCoord0.st;
    gl_Position = gl_ModelViewProjectionMatrix * vec4(p, 1.0);
}
