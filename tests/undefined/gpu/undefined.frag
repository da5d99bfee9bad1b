#version 130
#extension GL_ARB_shader_bit_encoding : require
// GLSL's undefined operations on the GPU: pixel column x computes case x of
// cases.txt and writes the 32 bits of its float (or int) result as R, G, B,
// A = bytes 0..3 (byte n as n / 255, which NVIDIA's conversion stores as n).
// The operands come from uniforms (z = 0.0, zi = 0) so that the compiler
// cannot fold them. decode.py reads the image back.
uniform float z;
uniform int zi;
void main() {
    int c = int(floor(gl_FragCoord.x));
    float arr[4];
    arr[0] = 1.0 + z; arr[1] = 2.0 + z; arr[2] = 3.0 + z; arr[3] = 4.0 + z;
    float r = 0.0;
    int ri = 0;
    bool isint = false;
    if (c == 0) { r = pow(-0.9 + z, 32.0 + z); }
    else if (c == 1) { r = pow(-2.0 + z, 2.0 + z); }
    else if (c == 2) { r = pow(-2.0 + z, 0.5 + z); }
    else if (c == 3) { r = pow(z, z); }
    else if (c == 4) { r = pow(z, -1.0 + z); }
    else if (c == 5) { r = log(z); }
    else if (c == 6) { r = log(-1.0 + z); }
    else if (c == 7) { r = log2(z); }
    else if (c == 8) { r = log2(-1.0 + z); }
    else if (c == 9) { r = sqrt(-1.0 + z); }
    else if (c == 10) { r = inversesqrt(z); }
    else if (c == 11) { r = inversesqrt(-1.0 + z); }
    else if (c == 12) { r = (1.0 + z) / z; }
    else if (c == 13) { r = (-1.0 + z) / z; }
    else if (c == 14) { r = z / z; }
    else if (c == 15) { r = asin(1.5 + z); }
    else if (c == 16) { r = acos(1.5 + z); }
    else if (c == 17) { r = acos(-1.5 + z); }
    else if (c == 18) { r = atan(z, z); }
    else if (c == 19) { r = normalize(vec3(z)).x; }
    else if (c == 20) { r = smoothstep(1.0 + z, z, 0.25 + z); }
    else if (c == 21) { r = smoothstep(0.5 + z, 0.5 + z, 0.25 + z); }
    else if (c == 22) { r = smoothstep(0.5 + z, 0.5 + z, 0.75 + z); }
    else if (c == 23) { r = clamp(0.5 + z, 1.0 + z, z); }
    else if (c == 24) { r = clamp(2.0 + z, 1.0 + z, z); }
    else if (c == 25) { ri = (7 + zi) / zi; isint = true; }
    else if (c == 26) { ri = (-7 + zi) / zi; isint = true; }
    else if (c == 27) { ri = zi / zi; isint = true; }
    else if (c == 28) { ri = (2147483647 + zi) + (1 + zi); isint = true; }
    else if (c == 29) { ri = (65536 + zi) * (65536 + zi); isint = true; }
    else if (c == 30) { ri = -((-2147483647 + zi) - 1); isint = true; }
    else if (c == 31) { ri = (2147483647 + zi) * (2 + zi); isint = true; }
    else if (c == 32) { r = arr[4 + zi]; }
    else if (c == 33) { r = arr[-1 + zi]; }
    else if (c == 34) { r = arr[1000 + zi]; }
    else if (c == 35) { float never; if (z > 1.0) never = 1.0; r = never; }
    else if (c == 36) { r = pow(-1.0 + z, 3.0 + z); }
    else if (c == 37) { r = log(-z); }
    else if (c == 38) { r = pow(-0.5 + z, 32.0 + z); }
    else if (c == 39) { r = smoothstep(1.0 + z, z, 0.75 + z); }
    uint bits = isint ? uint(ri) : floatBitsToUint(r);
    gl_FragColor = vec4(float(bits & 255u), float((bits >> 8) & 255u), float((bits >> 16) & 255u),
                        float(bits >> 24)) / 255.0;
}
