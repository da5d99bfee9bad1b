#version 120
#extension GL_ARB_shader_texture_lod : require
// The mipmap blend of 1D and cube-map textures (decode-free: Fast must render
// the GPU's image byte for byte, tests/scene/gpu_probes_test.cpp). Each pixel
// makes one textureLod-style lookup at a coordinate and lambda built from its
// position in exact binary fractions, and stores red and green in 16 bits
// (high, low byte). Lower half: texture1DLod on random levels 16..1, lambda
// in [-1/2, 7/2) in steps of 1/1024. Upper half: textureCubeLod on random
// faces with generated mipmaps, lambda in [-1/2, 7/2) likewise.
uniform sampler1D line;
uniform samplerCube cube;

vec2 bytes16(float v)
{
    float n = floor(v * 65535.0 + 0.5);
    float high = floor(n / 256.0);
    return vec2(high, n - high * 256.0) / 255.0;
}

void main()
{
    vec2 p = floor(gl_FragCoord.xy);
    float lambda = mod(p.x * 29.0 + p.y * 71.0, 4096.0) / 1024.0 - 0.5;
    vec4 c;
    if (p.y < 128.0) {
        c = texture1DLod(line, mod(p.x * 97.0 + p.y * 53.0, 8192.0) / 8192.0 + 1.0 / 16384.0, lambda);
    } else {
        float a = (mod(p.x * 37.0 + p.y * 11.0, 256.0) - 127.5) / 128.0;
        float b = (mod(p.x * 13.0 + p.y * 59.0, 256.0) - 127.5) / 128.0;
        float face = mod(p.x + p.y, 6.0);
        vec3 d = face < 1.0 ? vec3(1.0, a, b) : face < 2.0 ? vec3(-1.0, a, b) : face < 3.0 ? vec3(a, 1.0, b)
               : face < 4.0 ? vec3(a, -1.0, b) : face < 5.0 ? vec3(a, b, 1.0) : vec3(a, b, -1.0);
        c = textureCubeLod(cube, d, lambda);
    }
    gl_FragColor = vec4(bytes16(c.r), bytes16(c.g));
}
