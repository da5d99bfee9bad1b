uniform float shell;
uniform vec2 density;       // hair cells along s and t
uniform vec3 root_color, tip_color;

varying vec2 st;
varying float lit;

// A hair's length in (0, 1) per cell, from multiplies and fract only.
float hair(vec2 cell) {
    vec2 p = fract(cell * vec2(0.1031, 0.1030));
    p += dot(p, p.yx + 19.19);
    return fract((p.x + p.y) * p.x);
}

void main() {
    vec2 cell = floor(st * density);
    float length = hair(cell);
    if (shell > 0.0 && length < shell) discard;
    // Thinner towards the tip: the distance from the cell's centre.
    vec2 inside = fract(st * density) - 0.5;
    if (shell > 0.0 && dot(inside, inside) > 0.25 * (1.0 - shell)) discard;
    vec3 color = mix(root_color, tip_color, shell) * lit * (0.5 + 0.5 * shell);
    gl_FragColor = vec4(color, shell > 0.0 ? 1.0 - shell * 0.8 : 1.0);
}
