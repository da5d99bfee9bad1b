#version 400 compatibility
// The GPU only (GLSL 4.00): lambda of textureGrad for random derivative
// vectors. Level k of the texture is solid with green 28 k / 255, so a
// LINEAR_MIPMAP_LINEAR lookup's green in 16 bits (stored as high, low byte in
// red and green) is 257 * 28 * (k + w / 256): lambda's level and 8-bit
// weight. Each derivative component is +-(1 + f / 1024) 2^(e - 1) texels of level 0 (256)
// (e in 0..7), or 0 with probability 1/4; decode.py trigrad recomputes them.
uniform sampler2D tex;

uint hash(uint h)
{
    h = h * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    return (h >> 22u) ^ h;
}

float component(uint h)
{
    if ((h & 3u) == 0u) return 0.0;
    float v = float(1024u + ((h >> 2) & 1023u)) / 1024.0 * exp2(float((h >> 12) & 7u) - 1.0) / 256.0;
    return ((h >> 15) & 1u) == 1u ? -v : v;
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
    uint h1 = hash(p.x + 512u * p.y), h2 = hash(h1 ^ 0x5bd1e995u), h3 = hash(h2 ^ 0x1b873593u),
         h4 = hash(h3 ^ 0x85ebca6bu);
    vec2 dx = vec2(component(h1), component(h2)), dy = vec2(component(h3), component(h4));
    vec4 c = textureGrad(tex, vec2(0.5), dx, dy);
    gl_FragColor = vec4(bytes16(c.g), 0.0, 1.0);
}
