// 2x2 percentage-closer filtering of a depth texture compared by the sampler
// (GL_COMPARE_R_TO_TEXTURE): two taps through shadow2D, two through shadow2DProj.
uniform sampler2DShadow shadow_map;
uniform float texel;  // 1 / the shadow map's size
varying vec3 normal;
varying vec4 shadow_coord;
void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    float diffuse = max(dot(n, l), 0.0);
    vec3 p = shadow_coord.xyz / shadow_coord.w;
    float lit = shadow2D(shadow_map, p + vec3(-0.5 * texel, -0.5 * texel, 0.0)).r;
    lit += shadow2D(shadow_map, p + vec3(0.5 * texel, -0.5 * texel, 0.0)).r;
    lit += shadow2DProj(shadow_map, shadow_coord + vec4(-0.5, 0.5, 0.0, 0.0) * texel * shadow_coord.w).r;
    lit += shadow2DProj(shadow_map, shadow_coord + vec4(0.5, 0.5, 0.0, 0.0) * texel * shadow_coord.w).r;
    lit *= 0.25;
    vec3 c = gl_FrontMaterial.ambient.rgb * gl_LightModel.ambient.rgb
           + lit * diffuse * gl_FrontMaterial.diffuse.rgb * gl_LightSource[0].diffuse.rgb;
    gl_FragColor = vec4(c, 1.0);
}
