// Matrix-palette skinning: each vertex follows two of four bones, blended by
// its weights (attributes), then two lights per vertex (Gouraud).
uniform mat4 bones[4];
attribute vec2 weights;
attribute vec2 bone_index;   // GLSL 1.10 has no integer attributes
varying vec3 lit_color;
varying vec2 uv;

vec3 light_term(int i, vec3 position, vec3 n) {
    vec3 l = gl_LightSource[i].position.xyz - position * gl_LightSource[i].position.w;
    float d = length(l);
    l /= d;
    float attenuation = 1.0 / (gl_LightSource[i].constantAttenuation + gl_LightSource[i].linearAttenuation * d);
    vec3 h = normalize(l - normalize(position));
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess) : 0.0;
    return attenuation * (gl_FrontMaterial.diffuse.rgb * gl_LightSource[i].diffuse.rgb * diffuse +
                          gl_FrontMaterial.specular.rgb * gl_LightSource[i].specular.rgb * specular);
}

void main() {
    mat4 b0 = bones[int(bone_index.x)];
    mat4 b1 = bones[int(bone_index.y)];
    vec4 skinned = weights.x * (b0 * gl_Vertex) + weights.y * (b1 * gl_Vertex);
    vec3 skinned_normal = weights.x * mat3(b0[0].xyz, b0[1].xyz, b0[2].xyz) * gl_Normal +
                          weights.y * mat3(b1[0].xyz, b1[1].xyz, b1[2].xyz) * gl_Normal;
    vec3 position = vec3(gl_ModelViewMatrix * skinned);
    vec3 n = normalize(gl_NormalMatrix * skinned_normal);
    lit_color = gl_FrontMaterial.ambient.rgb * gl_LightModel.ambient.rgb + light_term(0, position, n) +
                light_term(1, position, n);
    uv = gl_MultiTexCoord0.st;
    gl_Position = gl_ModelViewProjectionMatrix * skinned;
}
