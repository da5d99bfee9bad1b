// ARB_shader_texture_lod in the fragment shader: an explicit Lod, and the
// Grad forms' gradients in place of ddx/ddy (the Proj form divides only the
// coordinate).
#extension GL_ARB_shader_texture_lod : require
uniform sampler2D tex;
uniform samplerCube env;

void main() {
    vec4 p = gl_TexCoord[0];
    gl_FragColor = texture2DLod(tex, p.xy, 1.5) + texture2DGradARB(tex, p.xy, p.zw, p.wz)
                 + texture2DProjGradARB(tex, p.xyz, p.zw, p.xy) + textureCubeGradARB(env, p.xyz, p.xyz, p.zyx);
}
