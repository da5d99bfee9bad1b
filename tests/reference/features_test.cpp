// glslrun against Mesa on what the lecture scenes leave out: user uniforms
// of every shape (struct members, arrays, matrices, ints, per-object
// overrides), user attributes, texture coordinates and the texture matrix,
// the current secondary colour, fog, a world-space clip plane, flat shading,
// culling with a clockwise front face, a reversed depth range and depth
// function. Scenes and shaders are inline, so these cases need no files.
#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const char* kCamera = R"(
[camera]
look_at = { eye = [0, 0, 4], center = [0, 0, 0], up = [0, 1, 0] }
perspective = { fovy = 50, near = 1, far = 20 }
)";

// --------------------------------------------- uniforms and attributes ---
const char* kUniformScene = R"(
[output]
size = [160, 120]
clear_color = [0.1, 0.1, 0.1, 1]

[state]
depth_test = true
clip_planes = [[1, 0, 0, 0.75]]  # world space: keeps x > -0.75

[current]
secondary_color = [0.1, 0.0, 0.2]

[fog]
color = [0.2, 0.3, 0.4, 1]
start = 2
end = 8

[texture_matrix.0]
transform = [ { scale = [2, 2, 1] } ]

[lights.0]
position = [1, 2, 3, 1]

[uniforms]
tint = [1, 0.8, 0.6, 1]
weights = [0.25, 0.5, 0.75]
swizzle = [[1, 0, 0], [0, 0, 1], [0, 1, 0]]
light = { pos = [0, 0.6, 0.8], color = [1, 0.9, 0.8] }
count = 1

# A plane, not the quad: with a user clip plane enabled llvmpipe draws
# GL_QUADS through Mesa's draw module, which splits them 0-1-3 / 1-2-3
# instead of 0-1-2 / 0-2-3; the split is implementation-dependent, and a
# non-affine attribute (weight) would show it.
[[objects]]
name = "plane"
mesh = "plane"
size = 2
vertex_colors = "normal"
transform = [ { translate = [-0.9, 0, 0] }, { rotate = [30, 0, 1, 0] }, { scale = [0.8, 0.8, 0.8] } ]
[objects.attributes]
weight = [0.0, 0.5, 1.0, 0.25]
[objects.uniforms]
count = 2
"weights[1]" = 1.5

[[objects]]
name = "sphere"
mesh = "sphere"
radius = 0.8
transform = [ { translate = [0.9, 0, -0.5] } ]
color = [0.3, 0.9, 0.5, 1]
)";

const char* kUniformVertex = R"(
attribute float weight;
uniform mat3 swizzle;
varying float w;
varying vec3 normal;
varying vec3 ecPos;
void main() {
    vec4 ec = gl_ModelViewMatrix * gl_Vertex;
    gl_Position = ftransform();
    gl_ClipVertex = ec;
    ecPos = ec.xyz;
    normal = gl_NormalMatrix * (swizzle * gl_Normal);
    w = weight;
    gl_FrontColor = gl_Color;
    gl_FrontSecondaryColor = gl_SecondaryColor;
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_FogFragCoord = abs(ec.z);
}
)";

const char* kUniformFragment = R"(
struct Light { vec3 pos; vec3 color; };
uniform Light light;
uniform vec4 tint;
uniform float weights[3];
uniform int count;
varying float w;
varying vec3 normal;
varying vec3 ecPos;
void main() {
    float s = 0.0;
    for (int i = 0; i < 3; ++i)
        if (i <= count) s += weights[i];
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - ecPos);
    float d = max(dot(n, l), 0.0) + 0.5 * max(dot(n, normalize(light.pos)), 0.0);
    vec3 base = gl_Color.rgb * tint.rgb * (0.2 + 0.2 * s) * d * light.color;
    base += gl_SecondaryColor.rgb + vec3(gl_TexCoord[0].st, w) * 0.2;
    float f = clamp((gl_Fog.end - gl_FogFragCoord) * gl_Fog.scale, 0.0, 1.0);
    gl_FragColor = vec4(mix(gl_Fog.color.rgb, base, f), 1.0);
}
)";

// ------------------------------------------- flat shading and culling ---
const char* kFlatScene = R"(
[output]
size = [128, 128]
clear_color = [0, 0, 0.2, 1]
clear_depth = 0.0

[state]
depth_test = true
depth_func = "greater"
depth_range = [1, 0]    # nearer is larger: "greater" keeps the nearest
cull_face = "front"
front_face = "cw"
shade_model = "flat"

[[objects]]
mesh = "quad"
transform = [ { translate = [-0.8, 0.6, 0] }, { scale = [0.6, 0.6, 0.6] } ]

[[objects]]
mesh = "torus"
inner_radius = 0.3
outer_radius = 0.9
transform = [ { translate = [0.3, -0.3, 0] }, { rotate = [60, 1, 0.3, 0] } ]
color = [1, 0.8, 0.6, 1]
)";

const char* kFlatVertex = R"(
void main() {
    gl_Position = ftransform();
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    gl_FrontColor = gl_Color * vec4(0.5 + 0.5 * n, 1.0);
}
)";

const char* kFlatFragment = "void main() { gl_FragColor = gl_Color; }\n";

reference::Inputs inline_inputs(const std::string& name, const std::string& toml, const char* vs, const char* fs) {
    auto scene = scene::parse_scene(toml, name + ".toml");
    if (!scene) FAIL(scene.error().str());
    return {{{name + ".vert", vs}}, {{name + ".frag", fs}}, std::move(*scene)};
}

}  // namespace

TEST_CASE("glslrun matches Mesa on uniforms, attributes, texture matrix, fog and clip planes", "[reference]") {
    std::string toml = std::string(kCamera) + kUniformScene;
    reference::compare("features-uniforms", inline_inputs("uniforms", toml, kUniformVertex, kUniformFragment));
}

TEST_CASE("glslrun matches Mesa on flat shading, culling, depth range and depth function", "[reference]") {
    std::string toml = std::string(kCamera) + kFlatScene;
    reference::compare("features-flat", inline_inputs("flat", toml, kFlatVertex, kFlatFragment));
}
