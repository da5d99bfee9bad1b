// The per-fragment operations of [state] (GL 2.1 §4.1): scissor, alpha test,
// stencil, depth mask, blending, logic op, colour mask and draw buffers. Key
// names are GL's state-table names in snake_case; enum values are GL's enum
// names without GL_ (docs/scene-format.md).
#include <fmt/format.h>

#include "scene/scene_reader.h"

namespace glslrun::scene::detail {

namespace {

const std::vector<std::string_view> kStencilOps = {"keep", "zero", "replace", "incr",
                                                   "decr", "invert", "incr_wrap", "decr_wrap"};
const std::vector<std::string_view> kBlendFactors = {
    "zero", "one", "src_color", "one_minus_src_color", "dst_color", "one_minus_dst_color", "src_alpha",
    "one_minus_src_alpha", "dst_alpha", "one_minus_dst_alpha", "constant_color", "one_minus_constant_color",
    "constant_alpha", "one_minus_constant_alpha", "src_alpha_saturate"};
const std::vector<std::string_view> kBlendEquations = {"func_add", "func_subtract", "func_reverse_subtract",
                                                       "min", "max"};
const std::vector<std::string_view> kLogicOps = {"clear", "and", "and_reverse", "copy", "and_inverted", "noop",
                                                 "xor", "or", "nor", "equiv", "invert", "or_reverse",
                                                 "copy_inverted", "or_inverted", "nand", "set"};

constexpr int64_t kStencilMax = (1 << kStencilBits) - 1;

template <class Enum>
void read_enum(const Section& s, std::string_view key, const std::vector<std::string_view>& names, Enum& out) {
    if (const toml::node* n = s.get(key)) out = Enum(choice(*n, s.name(key), names));
}

void read_stencil_value(const Section& s, std::string_view key, uint32_t& out) {
    const toml::node* n = s.get(key);
    if (!n) return;
    // GL masks these to the stencil buffer's bits; a larger value is a mistake.
    out = uint32_t(integer(*n, s.name(key) + fmt::format(" (stencil values are {} bits)", kStencilBits), 0,
                           kStencilMax));
}

// stencil_* keys set both faces (glStencilFunc, glStencilOp, glStencilMask),
// then stencil_back_* the back face alone (the *Separate calls with GL_BACK).
void read_stencil_face(const Section& s, std::string_view prefix, StencilFace& f) {
    auto key = [&](std::string_view name) { return fmt::format("{}{}", prefix, name); };
    read_enum(s, key("func"), compare_func_names(), f.func);
    uint32_t ref = uint32_t(f.ref);
    read_stencil_value(s, key("ref"), ref);
    f.ref = int(ref);
    read_stencil_value(s, key("value_mask"), f.value_mask);
    read_stencil_value(s, key("writemask"), f.write_mask);
    read_enum(s, key("fail"), kStencilOps, f.fail);
    read_enum(s, key("pass_depth_fail"), kStencilOps, f.depth_fail);
    read_enum(s, key("pass_depth_pass"), kStencilOps, f.depth_pass);
}

void read_scissor_box(const Section& s, GLState& gl) {
    const toml::node* n = s.get("scissor_box");
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a || a->size() != 4)
        fail(*n, fmt::format("'{}' must be [x, y, width, height] (got {})", s.name("scissor_box"), describe(*n)));
    const char* parts[] = {"x", "y", "width", "height"};
    for (size_t i = 0; i < 4; ++i) {
        // glScissor: a negative width or height is GL_INVALID_VALUE.
        int64_t lo = i < 2 ? -kMaxImageSide : 0;
        gl.scissor_box[i] = int(integer((*a)[i], fmt::format("{}.{}", s.name("scissor_box"), parts[i]), lo,
                                        int64_t(1) << 30));
    }
}

// blend_func: [src, dst] (glBlendFunc) or [src_rgb, dst_rgb, src_alpha, dst_alpha] (glBlendFuncSeparate).
void read_blend_func(const Section& s, BlendState& b) {
    const toml::node* n = s.get("blend_func");
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a || (a->size() != 2 && a->size() != 4))
        fail(*n, fmt::format("'{}' must be [src, dst] or [src_rgb, dst_rgb, src_alpha, dst_alpha] (got {})",
                             s.name("blend_func"), describe(*n)));
    std::array<BlendFactor, 4> f{};
    for (size_t i = 0; i < a->size(); ++i) {
        const toml::node& e = (*a)[i];
        f[i] = BlendFactor(choice(e, fmt::format("{}[{}]", s.name("blend_func"), i), kBlendFactors));
        // GL 2.1 allows SRC_ALPHA_SATURATE only as a source factor (GL_INVALID_ENUM otherwise).
        if (i % 2 == 1 && f[i] == BlendFactor::SrcAlphaSaturate)
            fail(e, fmt::format("'{}[{}]': \"src_alpha_saturate\" is a source factor only (GL 2.1 Table 4.2)",
                                s.name("blend_func"), i));
    }
    if (a->size() == 2) f[2] = f[0], f[3] = f[1];
    b.src_rgb = f[0], b.dst_rgb = f[1], b.src_alpha = f[2], b.dst_alpha = f[3];
}

// blend_equation: one mode (glBlendEquation) or [rgb, alpha] (glBlendEquationSeparate).
void read_blend_equation(const Section& s, BlendState& b) {
    const toml::node* n = s.get("blend_equation");
    if (!n) return;
    std::string what = s.name("blend_equation");
    if (const toml::array* a = n->as_array()) {
        if (a->size() != 2) fail(*n, fmt::format("'{}' must be one mode or [rgb, alpha] (got {})", what, describe(*n)));
        b.equation_rgb = BlendEquation(choice((*a)[0], what + "[0]", kBlendEquations));
        b.equation_alpha = BlendEquation(choice((*a)[1], what + "[1]", kBlendEquations));
        return;
    }
    b.equation_rgb = b.equation_alpha = BlendEquation(choice(*n, what, kBlendEquations));
}

void read_blend_color(const Section& s, BlendState& b) {
    const toml::node* n = s.get("blend_color");
    if (!n) return;
    glm::dvec4 c = color(*n, s.name("blend_color"));
    // GL 2.1 clamps the blend colour to [0, 1]; a value outside is a mistake worth reporting.
    for (int i = 0; i < 4; ++i) check_range(*n, s.name("blend_color"), c[i], {.lo = 0, .hi = 1, .why = "glBlendColor"});
    b.color = glm::vec4(c);
}

void read_color_writemask(const Section& s, GLState& gl) {
    const toml::node* n = s.get("color_writemask");
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a || a->size() != 4)
        fail(*n, fmt::format("'{}' must be 4 booleans [r, g, b, a] (got {})", s.name("color_writemask"),
                             describe(*n)));
    for (size_t i = 0; i < 4; ++i)
        gl.color_mask[i] = boolean((*a)[i], fmt::format("{}[{}]", s.name("color_writemask"), i));
}

}  // namespace

const std::vector<std::string_view>& compare_func_names() {
    static const std::vector<std::string_view> names = {"never", "less", "equal", "lequal",
                                                        "greater", "notequal", "gequal", "always"};
    return names;
}

const std::vector<std::string_view>& fragment_state_keys() {
    static const std::vector<std::string_view> keys = {
        "scissor_test", "scissor_box", "alpha_test", "alpha_test_func", "alpha_test_ref", "stencil_test",
        "stencil_func", "stencil_ref", "stencil_value_mask", "stencil_writemask", "stencil_fail",
        "stencil_pass_depth_fail", "stencil_pass_depth_pass", "stencil_back_func", "stencil_back_ref",
        "stencil_back_value_mask", "stencil_back_writemask", "stencil_back_fail", "stencil_back_pass_depth_fail",
        "stencil_back_pass_depth_pass", "depth_writemask", "blend", "blend_func", "blend_equation", "blend_color",
        "color_logic_op", "logic_op_mode", "color_writemask", "draw_buffers"};
    return keys;
}

void read_fragment_state(const Section& s, GLState& gl) {
    s.read("scissor_test", gl.scissor_test);
    read_scissor_box(s, gl);
    s.read("alpha_test", gl.alpha_test);
    read_enum(s, "alpha_test_func", compare_func_names(), gl.alpha_func);
    s.read("alpha_test_ref", gl.alpha_ref, {.lo = 0, .hi = 1, .why = "glAlphaFunc"});
    s.read("stencil_test", gl.stencil_test);
    for (StencilFace& face : gl.stencil) read_stencil_face(s, "stencil_", face);
    read_stencil_face(s, "stencil_back_", gl.stencil[1]);
    s.read("depth_writemask", gl.depth_mask);
    s.read("blend", gl.blend);
    read_blend_func(s, gl.blend_state);
    read_blend_equation(s, gl.blend_state);
    read_blend_color(s, gl.blend_state);
    s.read("color_logic_op", gl.color_logic_op);
    read_enum(s, "logic_op_mode", kLogicOps, gl.logic_op);
    read_color_writemask(s, gl);
    if (const toml::node* n = s.get("draw_buffers"))
        gl.draw_buffers = int(integer(*n, s.name("draw_buffers") + " (GL_MAX_DRAW_BUFFERS is 8)", 1, kMaxDrawBuffers));
}

}  // namespace glslrun::scene::detail
