// The mipmap blend of biased implicit lookups (decode-free: Fast must render
// the GPU's image byte for byte, tests/scene/gpu_probes_test.cpp). Each 2x2
// quad's coordinates step by g = (1 + f / 64) 2^k / 8 along s and t (exact
// binary fractions, so the derivatives are exactly g: rho = 8 g on the 8x8
// level 0), and texture2D adds a bias in [-1, 3) in steps of 1/1024; the upper
// half's texture also has GL_TEXTURE_LOD_BIAS 0.3. Red and green in 16 bits.
uniform sampler2D tex, biased;

vec2 bytes16(float v)
{
    float n = floor(v * 65535.0 + 0.5);
    float high = floor(n / 256.0);
    return vec2(high, n - high * 256.0) / 255.0;
}

void main()
{
    vec2 p = floor(gl_FragCoord.xy), q = floor(p / 2.0);
    float f = mod(q.x * 7.0 + q.y * 13.0, 64.0), k = mod(q.x * 3.0 + q.y * 5.0, 4.0) - 1.0;
    float g = (1.0 + f / 64.0) * exp2(k) / 8.0;
    vec2 base = vec2(mod(q.x * 37.0 + q.y * 101.0, 256.0), mod(q.x * 53.0 + q.y * 29.0, 256.0)) / 256.0;
    vec2 st = base + (p - 2.0 * q) * g;
    float bias = mod(q.x * 41.0 + q.y * 67.0, 4096.0) / 1024.0 - 1.0;
    vec4 c = p.y < 128.0 ? texture2D(tex, st, bias) : texture2D(biased, st, bias);
    gl_FragColor = vec4(bytes16(c.r), bytes16(c.g));
}
