uniform sampler3D volume;
uniform float opacity;
varying vec3 stp;
void main() {
    vec3 p = stp - 0.5;
    // a soft ball of coloured fog: density falls off from the centre
    float density = clamp(1.0 - dot(p, p) * 4.0, 0.0, 1.0);
    vec3 color = texture3D(volume, stp * 1.5).rgb;
    gl_FragColor = vec4(color, density * opacity);
}
