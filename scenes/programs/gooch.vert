// Gooch shading with hatching, as the NPR chapters of the era wrote it: the
// light's direction from gl_LightSource, a warm/cool ramp in the fragment
// shader and pen strokes from screen position.
varying vec3 normal;
varying vec3 to_light;
varying vec3 to_eye;
varying float diffuse;

void main() {
    vec4 eye_pos = gl_ModelViewMatrix * gl_Vertex;
    normal = normalize(gl_NormalMatrix * gl_Normal);
    to_light = normalize(gl_LightSource[0].position.xyz - eye_pos.xyz);
    to_eye = -eye_pos.xyz;
    diffuse = max(dot(normal, to_light), 0.0);
    gl_Position = ftransform();
}
