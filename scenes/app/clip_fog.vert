// Two-sided per-vertex lighting from GL_LIGHT0 (the back colour lit with the
// flipped normal and the back material), user clip planes through
// gl_ClipVertex, and the fog distance in gl_FogFragCoord.
vec4 lit(vec3 n, vec3 l, gl_MaterialParameters m) {
    float d = max(dot(n, l), 0.0);
    return m.emission + m.ambient * gl_LightModel.ambient + m.ambient * gl_LightSource[0].ambient
         + m.diffuse * gl_LightSource[0].diffuse * d;
}
void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - eye.xyz);
    gl_FrontColor = lit(n, l, gl_FrontMaterial);
    gl_BackColor = lit(-n, l, gl_BackMaterial);
    gl_ClipVertex = eye;
    gl_FogFragCoord = length(eye.xyz);
    gl_Position = ftransform();
}
