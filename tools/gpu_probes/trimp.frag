#version 400 compatibility
// The GPU only (GLSL 4.00): the weight of each texel in NVIDIA's mipmap blend.
// The textures (trimp_*.toml) hold one texel of value 1 per channel among the
// four taps of level 0 (impulses0) or of level 1 (impulses1), 0 elsewhere, so a
// lookup's channel is that texel's weight. Each pixel stores two channels
// (which = 0: red, green; 1: blue, alpha) in 16 bits each (high, low byte).
// Coordinates keep the taps on level 0's texels 1..2 (level 1's 0..1).
//   mode 0: textureLod at lambda in [0, 1) (12 fraction bits)
//   mode 1: textureGrad, isotropic, rho = 4 g in [1, 2) (10 significand bits)
//   mode 2: texture() on a 2x2 quad whose coordinates step by mode 1's g
uniform sampler2D tex;
uniform int mode;
uniform int which;

uint hash(uint h)
{
    h = h * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    return (h >> 22u) ^ h;
}

vec2 bytes16(float v)
{
    float n = floor(v * 65535.0 + 0.5);
    float high = floor(n / 256.0);
    return vec2(high, n - high * 256.0) / 255.0;
}

void main()
{
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint key = mode == 2 ? (p.x >> 1) + 256u * (p.y >> 1) : p.x + 512u * p.y;
    uint h1 = hash(key), h2 = hash(h1 ^ 0x5bd1e995u);
    // s, t in [3/8, 5/8) (level 0: u in [1, 2) + 1/2), 14 fraction bits.
    vec2 st = vec2(0.375) + vec2(float(h1 & 0x3fffu), float((h1 >> 16) & 0x3fffu)) / 65536.0;
    float g = float(1024u + (h2 & 1023u)) / 4096.0;
    vec4 c;
    if (mode == 0) {
        c = textureLod(tex, st, float(h2 >> 20) / 4096.0);
    } else if (mode == 1) {
        c = textureGrad(tex, st, vec2(g, 0.0), vec2(0.0, g));
    } else {
        // The quad's first pixel at st, the others g further along s and t:
        // the decoder keeps the pixels whose taps stay on those texels.
        c = texture(tex, st + vec2(float(p.x & 1u), float(p.y & 1u)) * g);
    }
    gl_FragColor = which == 0 ? vec4(bytes16(c.r), bytes16(c.g)) : vec4(bytes16(c.b), bytes16(c.a));
}
