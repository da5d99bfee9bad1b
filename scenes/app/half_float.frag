// Bands of 8 rows into the RGBA16F target: ties between halves, values
// just past them, finite overflow, half subnormals, the clamped vertex
// colour, negative ties, and a band that half_float_add.frag adds to.
void main() {
    float i = floor(gl_FragCoord.x);
    float band = floor(gl_FragCoord.y / 8.0);
    vec4 c = vec4(0.0);
    if (band < 1.0) c.r = 1.0 + (i + 0.5) / 1024.0;
    else if (band < 2.0) c.r = 1.0 + (i + 0.5) / 1024.0 + 1.0 / 1048576.0;
    else if (band < 3.0) c = vec4(65504.0 + i * 64.0, 1.0e6 * i, -65504.0 - i * 64.0, 0.0);
    else if (band < 4.0) c.r = (i + 0.5) / 16777216.0;
    else if (band < 5.0) c = gl_Color;
    else if (band < 6.0) c.r = -(1.0 + (i + 0.5) / 1024.0);
    else c = vec4(1.0, 1.0, 60000.0, 1.0);
    gl_FragColor = c;
}
