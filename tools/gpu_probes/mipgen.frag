#version 110
// Mipmap generation probe: the generated levels of two textures, each texel of level L on one pixel,
// written as it is stored (decode.py mipgen). Rows 0-63: rand128.png (128x128 RGBA), level L of
// size w = 128 >> L at x in [128 - 2w, 128 - w), rows [0, w). Rows 64-127: wood.png (64x64 RGB)
// likewise, w = 64 >> L at x in [64 - 2w, 64 - w). One pixel steps one texel of level L, so
// lambda = log2(2^L) = L and NEAREST_MIPMAP_NEAREST samples level L at the texel's centre.
uniform sampler2D rnd, wood;
void main() {
    float X = floor(gl_FragCoord.x);
    float Y = floor(gl_FragCoord.y);
    float n = Y < 64.0 ? 128.0 : 64.0;
    float y = Y < 64.0 ? Y : Y - 64.0;
    // the level's size: the largest w = n / 2^L with n - 2w <= X
    float w = n / 2.0;
    for (int k = 0; k < 7; ++k)
        if (X >= n - w && w > 1.0) w = w / 2.0;
    float x0 = n - 2.0 * w;
    vec2 st = vec2((X - x0 + 0.5) / w, (y + 0.5) / w);
    if (X >= n - 1.0 || y >= w) gl_FragColor = vec4(0.0);
    else if (Y < 64.0) gl_FragColor = texture2D(rnd, st);
    else gl_FragColor = texture2D(wood, st);
}
