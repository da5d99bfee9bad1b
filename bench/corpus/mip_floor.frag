uniform sampler2D tiles;
uniform vec3 horizon;
varying vec2 uv;
varying float dist;
void main() {
    vec3 c = texture2D(tiles, uv).rgb;
    float haze = clamp((dist - 10.0) / 60.0, 0.0, 1.0);
    gl_FragColor = vec4(mix(c, horizon, haze * haze), 1.0);
}
