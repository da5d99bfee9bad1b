#version 450 compatibility
// The GPU only (GLSL 4.50): textured_pix's lookup with the derivatives the
// shader sees. which = 0, 1: the 16-bit red and green of textureGrad with
// coarse (0) or fine (1) derivatives (as textured_texel.frag); which = 2..5:
// the float bits of dFdxCoarse(s), dFdxCoarse(t), dFdyCoarse(s), dFdyCoarse(t).
uniform sampler2D tex;
uniform int which;

vec2 bytes16(float v)
{
    float n = floor(v * 65535.0 + 0.5);
    float high = floor(n / 256.0);
    return vec2(high, n - high * 256.0) / 255.0;
}

vec4 bits(float v)
{
    uint b = floatBitsToUint(v);
    return vec4(float(b >> 24), float((b >> 16) & 255u), float((b >> 8) & 255u), float(b & 255u)) / 255.0;
}

void main()
{
    vec2 st = gl_TexCoord[0].st;
    vec2 dx = dFdxCoarse(st), dy = dFdyCoarse(st);
    if (which == 0) {
        vec4 t = textureGrad(tex, st, dx, dy);
        gl_FragColor = vec4(bytes16(t.r), bytes16(t.g));
    } else if (which == 1) {
        vec4 t = textureGrad(tex, st, dFdxFine(st), dFdyFine(st));
        gl_FragColor = vec4(bytes16(t.r), bytes16(t.g));
    } else {
        gl_FragColor = bits(which == 2 ? dx.x : which == 3 ? dx.y : which == 4 ? dy.x : dy.y);
    }
}
