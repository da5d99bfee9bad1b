// vertex-stage lookups: level 0, or the explicit Lod
uniform sampler2D tex;
uniform samplerCube env;
varying vec4 color;
void main() {
    color = texture2D(tex, gl_MultiTexCoord0.st) + textureCubeLod(env, gl_Normal, 2.0);
    gl_Position = ftransform();
}
