// Added with (GL_ONE, GL_ONE) to the last band: the float blend's sum is
// stored as a half like any draw.
void main() {
    float i = floor(gl_FragCoord.x);
    float band = floor(gl_FragCoord.y / 8.0);
    gl_FragColor = band < 6.0 ? vec4(0.0) : vec4((i + 0.5) / 1024.0, (i + 0.5) / 1024.0 + 1.0 / 1048576.0, 1.0, 0.0);
}
