uniform vec3 brick_color, mortar_color;
uniform vec2 brick_size, brick_pct;

varying vec2 mc_position;
varying float intensity;

// The integral of the 1D pulse of width pct repeated every 1.
vec2 pulse_integral(vec2 x, vec2 pct) {
    return floor(x) * pct + max(fract(x) - (1.0 - pct), 0.0);
}

void main() {
    vec2 position = mc_position / brick_size;
    if (fract(position.y * 0.5) > 0.5) position.x += 0.5;
    // A side of the cube has a constant coordinate: keep the filter's
    // width above zero rather than divide 0 by 0.
    vec2 fw = max(fwidth(position), vec2(1.0e-4));
    vec2 use_brick = (pulse_integral(position + fw * 0.5, brick_pct)
                    - pulse_integral(position - fw * 0.5, brick_pct)) / fw;
    // Where the filter is narrower than a texel of brick, fall back on a
    // smoothstep edge, as the book's version with dFdx did.
    vec2 edge = smoothstep(brick_pct - fw, brick_pct, fract(position));
    vec2 mask = mix(1.0 - edge, use_brick, step(0.02, fw));
    vec3 color = mix(mortar_color, brick_color, mask.x * mask.y) * intensity;
    gl_FragColor = vec4(color, 1.0);
}
