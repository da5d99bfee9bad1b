#version 120
// A height field displaced in the vertex shader: the height read from a
// texture with texture2DLod (vertex texture fetch, as the NVIDIA SDK's
// GeForce 6 terrain sample did), plus a sine swell, the normal from central
// differences carried through a 3x2 matrix of the tangent and bitangent.
invariant gl_Position;

uniform sampler2D height_map;
uniform float height_scale;
uniform float wave;

centroid varying vec3 normal;
varying vec3 position;
varying float height;

float height_at(vec2 st) {
    float h = texture2DLod(height_map, st, 0.0).r * height_scale;
    return h + 0.05 * sin(st.x * 12.0 + wave) * cos(st.y * 9.0);
}

void main() {
    vec2 st = gl_MultiTexCoord0.st;
    const float d = 1.0 / 32.0;
    float h = height_at(st);
    float hx = height_at(st + vec2(d, 0.0)) - height_at(st - vec2(d, 0.0));
    float hy = height_at(st + vec2(0.0, d)) - height_at(st - vec2(0.0, d));
    // Columns: the surface's tangent and bitangent in object space (the
    // plane spans 2 units over st's 1).
    mat2x3 frame = mat2x3(vec3(4.0 * d, 0.0, hx), vec3(0.0, 4.0 * d, hy));
    vec3 n = cross(frame[0], frame[1]);
    vec4 displaced = gl_Vertex + vec4(0.0, 0.0, h, 0.0);
    normal = gl_NormalMatrix * n;
    position = vec3(gl_ModelViewMatrix * displaced);
    height = h / height_scale;
    gl_Position = gl_ModelViewProjectionMatrix * displaced;
}
