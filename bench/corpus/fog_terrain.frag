// GL_EXP2 fog from gl_Fog, as the fixed-function pipeline computed it, and
// snow above a height.
varying vec3 color;
varying float height;
void main() {
    const float LOG2E = 1.442695;
    float f = exp2(-gl_Fog.density * gl_Fog.density * gl_FogFragCoord * gl_FogFragCoord * LOG2E);
    f = clamp(f, 0.0, 1.0);
    vec3 c = mix(color, vec3(0.95), smoothstep(1.2, 1.6, height));
    gl_FragColor = vec4(mix(gl_Fog.color.rgb, c, f), 1.0);
}
