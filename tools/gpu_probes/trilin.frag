#version 400 compatibility
// The GPU only (GLSL 4.00): NVIDIA's mipmap blend under control. Each pixel
// stores the raw float bits of one lookup's red channel (bytes, most
// significant first), so that nothing of the filter's precision is lost.
// Coordinates, lambdas and derivatives come from a hash of the pixel index
// in exact binary fractions; decode.py trilin recomputes them.
//   mode 0: textureLod at lambda = i / 65536 - 1/2 (i the pixel index), a
//           coordinate per pixel; levels alternately 0 and 1: the weight of lambda
//   mode 1: textureLod at a random coordinate (16 fraction bits) and a random
//           lambda in [-1/2, 7/2) (10 fraction bits): the blend of random levels
//   mode 2: textureGrad with random isotropic derivatives (rho = 8 g, g's
//           significand 10 bits): the implicit lambda's blend
//   mode 3: texture() on a 2x2 quad whose coordinates step by mode 2's g
//   mode 4: textureQueryLod(...).y of mode 3's quads (lambda's bits)
uniform sampler2D tex;
uniform int mode;

uint hash(uint h)
{
    h = h * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    return (h >> 22u) ^ h;
}

vec4 bytes(float v)
{
    uint b = floatBitsToUint(v);
    return vec4(float(b >> 24), float((b >> 16) & 255u), float((b >> 8) & 255u), float(b & 255u)) / 255.0;
}

// mode 2's derivative: (1 + f / 1024) 2^(e - 1) / 8, e in 0..3.
float grad(uint h)
{
    return float(1024u + (h & 1023u)) / 1024.0 * exp2(float((h >> 10) & 3u) - 1.0) / 8.0;
}

void main()
{
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint i = p.x + 512u * p.y;
    // Per quad for modes 3 and 4, per pixel otherwise.
    uint key = mode >= 3 ? (p.x >> 1) + 256u * (p.y >> 1) : i;
    uint h1 = hash(key), h2 = hash(h1 ^ 0x5bd1e995u), h3 = hash(h2 ^ 0x1b873593u);
    vec2 st = vec2(float(h1 & 0xffffu), float(h1 >> 16)) / 65536.0;
    float v;
    if (mode == 0) {
        v = textureLod(tex, st, float(i) / 65536.0 - 0.5).r;
    } else if (mode == 1) {
        v = textureLod(tex, st, float(h2 & 4095u) / 1024.0 - 0.5).r;
    } else if (mode == 2) {
        float g = grad(h3);
        v = textureGrad(tex, st, vec2(g, 0.0), vec2(0.0, g)).r;
    } else {
        float g = grad(h3);
        vec2 q = st + vec2(float(p.x & 1u), float(p.y & 1u)) * g;
        v = mode == 3 ? texture(tex, q).r : textureQueryLod(tex, q).y;
    }
    gl_FragColor = bytes(v);
}
