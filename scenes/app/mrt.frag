// A G-buffer of the era through ARB_draw_buffers: albedo, the eye-space
// normal mapped to [0, 1], and lighting with the eye depth.
#extension GL_ARB_draw_buffers : enable
varying vec3 normal;
varying vec4 eye;
uniform float opacity;
void main() {
    vec3 n = normalize(normal);
    float d = max(dot(n, normalize(gl_LightSource[0].position.xyz - eye.xyz)), 0.0);
    gl_FragData[0] = vec4(gl_Color.rgb, opacity);
    gl_FragData[1] = vec4(n * 0.5 + 0.5, opacity);
    gl_FragData[2] = vec4(vec3(d), -eye.z / 8.0);
}
