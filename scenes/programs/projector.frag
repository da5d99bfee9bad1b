uniform sampler2D ground;
uniform sampler2D slide;

varying vec3 normal;
varying vec3 position;

void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - position);
    vec4 lit = gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[0].diffuse * max(dot(n, l), 0.0);
    vec4 base = texture2D(ground, gl_TexCoord[0].st);
    // Only in front of the projector, and only inside its frustum.
    vec4 projected = gl_TexCoord[1].q > 0.0 ? texture2DProj(slide, gl_TexCoord[1]) : vec4(0.0);
    gl_FragColor = vec4(lit.rgb * base.rgb + projected.rgb * 0.8, 1.0);
}
