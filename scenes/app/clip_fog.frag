// Linear fog from gl_Fog, as GL's fixed function would apply it.
void main() {
    float f = clamp((gl_Fog.end - gl_FogFragCoord) * gl_Fog.scale, 0.0, 1.0);
    gl_FragColor = vec4(mix(gl_Fog.color.rgb, gl_Color.rgb, f), gl_Color.a);
}
