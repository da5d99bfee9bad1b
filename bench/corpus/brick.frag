uniform vec3 brick_color, mortar_color;
uniform vec2 brick_size;     // one brick and its mortar
uniform vec2 brick_fraction; // the brick's share of brick_size
varying float intensity;
varying vec2 pattern_position;

void main() {
    vec2 p = pattern_position / brick_size;
    if (fract(p.y * 0.5) > 0.5)  // every other row shifted by half a brick
        p.x += 0.5;
    p = fract(p);
    vec2 use_brick = step(p, brick_fraction);
    vec3 color = mix(mortar_color, brick_color, use_brick.x * use_brick.y);
    gl_FragColor = vec4(color * (0.25 + intensity), 1.0);
}
