// A transparent pass: the object's colour at alpha 0.4, blended over what the passes before drew.
void main() { gl_FragColor = vec4(gl_Color.rgb, 0.4); }
