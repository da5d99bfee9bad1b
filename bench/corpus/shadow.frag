uniform sampler2DShadow shadow_map;
uniform float texel;         // 1 / the shadow map's size
uniform float depth_bias;
varying vec4 shadow_coord;
varying vec3 normal, position;

float lit_fraction(vec4 coord) {
    coord.z -= depth_bias * coord.w;
    float sum = 0.0;
    sum += shadow2DProj(shadow_map, coord + vec4(-0.5, -0.5, 0.0, 0.0) * texel * coord.w).r;
    sum += shadow2DProj(shadow_map, coord + vec4(0.5, -0.5, 0.0, 0.0) * texel * coord.w).r;
    sum += shadow2DProj(shadow_map, coord + vec4(-0.5, 0.5, 0.0, 0.0) * texel * coord.w).r;
    sum += shadow2DProj(shadow_map, coord + vec4(0.5, 0.5, 0.0, 0.0) * texel * coord.w).r;
    return sum * 0.25;
}

void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    float diffuse = max(dot(n, l), 0.0);
    float lit = lit_fraction(shadow_coord);
    vec3 color = gl_FrontMaterial.ambient.rgb * gl_LightModel.ambient.rgb +
                 gl_FrontMaterial.diffuse.rgb * gl_LightSource[0].diffuse.rgb * diffuse * lit;
    gl_FragColor = vec4(color, 1.0);
}
