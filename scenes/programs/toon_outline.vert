// The outline pass: back faces pushed out along their normals in eye space,
// drawn in the ink colour behind the cel-shaded front faces.
uniform float outline_width;

void main() {
    vec4 eye_pos = gl_ModelViewMatrix * gl_Vertex;
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    eye_pos.xyz += n * outline_width * -eye_pos.z * 0.01;
    gl_Position = gl_ProjectionMatrix * eye_pos;
}
