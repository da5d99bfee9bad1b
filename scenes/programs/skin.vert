#version 120
// Matrix-palette skinning as the NVIDIA and ATI SDKs' skinned-character
// samples did it: a uniform array of bone matrices, per-vertex bone
// weights and indices as generic attributes, the normal skinned by the
// same matrices, lit per vertex from gl_LightSource and gl_FrontMaterial.
const int kBones = 4;
uniform mat4 bones[kBones];

attribute vec4 weights;
attribute vec4 indices;

varying vec4 color;

void main() {
    mat4 skin = mat4(0.0);
    for (int i = 0; i < 4; ++i)
        skin += bones[int(indices[i])] * weights[i];
    vec4 position = skin * gl_Vertex;
    vec3 normal = normalize(gl_NormalMatrix * (mat3(skin[0].xyz, skin[1].xyz, skin[2].xyz) * gl_Normal));
    vec4 eye_pos = gl_ModelViewMatrix * position;
    vec3 l = normalize(gl_LightSource[0].position.xyz - eye_pos.xyz);
    vec3 h = normalize(l - normalize(eye_pos.xyz));
    color = gl_FrontLightModelProduct.sceneColor
          + gl_FrontLightProduct[0].diffuse * max(dot(normal, l), 0.0)
          + gl_FrontLightProduct[0].specular * pow(max(dot(normal, h), 0.0), gl_FrontMaterial.shininess);
    gl_Position = gl_ModelViewProjectionMatrix * position;
}
