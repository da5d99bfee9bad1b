// Pass 1 of scenes/multi_pass.toml: depth and the ambient term.
void main() {
    gl_FrontColor = gl_FrontMaterial.ambient * gl_LightModel.ambient + gl_FrontMaterial.emission;
    gl_Position = ftransform();
}
