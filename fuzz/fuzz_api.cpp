// libFuzzer target: the C++ API driven as a caller might misuse it. The
// fuzz data picks one of a few programs, then a sequence of calls with
// arbitrary arguments: uniforms by name or not, of any count; textures of
// any target, format and size (enums outside their values, images whose
// texels do not match their size); bindings on any unit; GL state with
// arbitrary enum bytes; framebuffers of any size and colour-buffer count;
// draws, run_vertices and run_fragments with any counts, attributes and
// indices. Every call must return (an Error is fine); a crash, a sanitizer
// report, an exception or a hang is a finding. Draws stay small: the
// framebuffers that are accepted are at most 64x64 and the instruction
// budgets are small, so one input runs in milliseconds.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"

using namespace glslrun;

namespace {

// The fuzz data as a stream of choices; zeros once it runs out.
class Bytes {
public:
    Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    bool empty() const { return pos_ >= size_; }
    uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
    uint32_t u32() {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v = v << 8 | byte();
        return v;
    }
    int32_t i32() { return int32_t(u32()); }
    float f32() {
        uint32_t bits = u32();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
    }
    // A count: mostly small, sometimes one of the extremes.
    uint32_t count(uint32_t small) {
        switch (byte() % 8) {
        case 0: return u32();
        case 1: return UINT32_MAX;
        case 2: return 0;
        default: return byte() % (small + 1);
        }
    }
    template <class E>
    E as_enum() {  // any byte, in range or not, as a cast from an int gives it
        E e;
        uint8_t b = byte();
        static_assert(sizeof(E) == 1 || sizeof(E) == 4);
        if constexpr (sizeof(E) == 1) {
            std::memcpy(&e, &b, 1);
        } else {
            int32_t v = b < 240 ? b % 16 : int32_t(0xFFFFFF00u | b);
            std::memcpy(&e, &v, 4);
        }
        return e;
    }
    std::string name() {
        static const char* names[] = {"u", "f", "v", "m", "i", "s", "arr", "arr[1]", "arr[7]", "st.x",
                                      "gl_ModelViewMatrix", "tex", "", "u[0]", "u[-1]", "v.x"};
        uint8_t b = byte();
        if (b < 240) return names[b % 16];
        std::string raw;
        for (int n = byte() % 12; n > 0; --n) raw.push_back(char(byte()));
        return raw;
    }

private:
    const uint8_t* data_;
    size_t size_;
    size_t pos_ = 0;
};

const char* kVertex[] = {
    "void main() { gl_Position = gl_Vertex; gl_TexCoord[0] = gl_MultiTexCoord0; gl_FrontColor = gl_Color; }\n",
    "uniform mat4 m; uniform vec4 v; attribute vec4 a;\n"
    "void main() { gl_Position = m * gl_Vertex + a * 0.0; gl_FrontColor = v; gl_PointSize = 3.0; }\n",
};
const char* kFragment[] = {
    "uniform sampler2D tex; uniform float f;\n"
    "void main() { gl_FragColor = texture2D(tex, gl_TexCoord[0].st) * f + gl_Color; }\n",
    "uniform int i; uniform float arr[8]; uniform samplerCube s; uniform sampler3D t3;\n"
    "void main() { float x = 0.0; for (int k = 0; k < i; ++k) x += arr[k - (k / 8) * 8];\n"
    "  gl_FragData[0] = vec4(x) + textureCube(s, vec3(gl_FragCoord.xy, 1.0)) + texture3D(t3, vec3(0.5));\n"
    "  gl_FragData[1] = gl_Color; if (x > 3.0) discard; }\n",
};

std::vector<float> values(Bytes& in, size_t most) {
    std::vector<float> v(std::min<size_t>(in.byte(), most));
    for (float& f : v) f = in.f32();
    return v;
}

std::shared_ptr<Texture> texture(Bytes& in) {
    auto target = in.as_enum<TextureTarget>();
    auto format = in.as_enum<TextureFormat>();
    std::vector<TextureImage> faces(in.byte() % 8);
    for (TextureImage& face : faces) {
        face.width = int(in.count(8)), face.height = int(in.count(8)), face.depth = int(in.count(4));
        // The texels the caller gives, which need not match the size.
        face.texels.resize(std::min<size_t>(in.byte(), 256), glm::vec4(in.f32(), 0.5f, 0.25f, 1.0f));
    }
    auto created = Texture::create(target, std::move(faces), format);
    if (!created) return nullptr;
    auto t = std::make_shared<Texture>(std::move(created.value()));
    if (in.byte() & 1) (void)t->set_level(in.i32() % 8, in.i32() % 16, TextureImage{int(in.count(4)), 1, 1, {}});
    if (in.byte() & 1) t->generate_mipmaps();
    t->sampler.min_filter = in.as_enum<TextureFilter>();
    t->sampler.mag_filter = in.as_enum<TextureFilter>();
    t->sampler.wrap_s = in.as_enum<TextureWrap>();
    t->sampler.compare = in.byte() & 1;
    t->sampler.compare_func = in.as_enum<CompareFunc>();
    t->sampler.depth_mode = in.as_enum<DepthTextureMode>();
    t->sampler.base_level = in.i32() % 20;
    t->sampler.max_level = in.i32();
    t->sampler.lod_bias = in.f32();
    return t;
}

void scramble_state(Bytes& in, GLState& gl) {
    switch (in.byte() % 12) {
    case 0: gl.depth_test = true, gl.depth_func = in.as_enum<CompareFunc>(); break;
    case 1: gl.alpha_test = true, gl.alpha_func = in.as_enum<CompareFunc>(), gl.alpha_ref = in.f32(); break;
    case 2:
        gl.stencil_test = true;
        gl.stencil[in.byte() & 1] = {in.as_enum<CompareFunc>(), in.i32(), in.u32(), in.u32(),
                                     in.as_enum<StencilOp>(), in.as_enum<StencilOp>(), in.as_enum<StencilOp>()};
        break;
    case 3:
        gl.blend = true;
        gl.blend_state = {in.as_enum<BlendFactor>(), in.as_enum<BlendFactor>(), in.as_enum<BlendFactor>(),
                          in.as_enum<BlendFactor>(), in.as_enum<BlendEquation>(), in.as_enum<BlendEquation>(),
                          glm::vec4(in.f32())};
        break;
    case 4: gl.color_logic_op = true, gl.logic_op = in.as_enum<LogicOp>(); break;
    case 5: gl.polygon_mode = {in.as_enum<PolygonMode>(), in.as_enum<PolygonMode>()}; break;
    case 6: gl.viewport = {in.i32(), in.i32(), in.i32(), in.i32()}; break;
    case 7: gl.scissor_test = true, gl.scissor_box = {in.i32(), in.i32(), in.i32(), in.i32()}; break;
    case 8: gl.draw_buffers = in.i32() % 12; break;
    case 9: gl.line_width = in.f32(), gl.point_size = in.f32(), gl.vertex_program_point_size = in.byte() & 1; break;
    case 10: gl.cull_face = true, gl.cull_back = in.byte() & 1, gl.front_ccw = in.byte() & 1; break;
    default: gl.clip_plane_enabled = in.u32(), gl.clip_planes[in.byte() % 6] = glm::vec4(in.f32()); break;
    }
}

std::vector<VertexAttrib> attributes(Bytes& in) {
    static const char* names[] = {"gl_Vertex", "gl_Color", "gl_MultiTexCoord0", "a", "gl_FragCoord", "nothing"};
    std::vector<VertexAttrib> attribs(in.byte() % 4);
    for (VertexAttrib& a : attribs) {
        a.name = names[in.byte() % 6];
        a.components = in.byte() % 6;
        a.data = values(in, 64);
    }
    return attribs;
}

void call(Bytes& in, Program& p, GLState& gl, std::unique_ptr<Framebuffer>& fb) {
    switch (in.byte() % 10) {
    case 0: {
        std::vector<float> v = values(in, 80);
        (void)p.set_uniform(in.name(), std::span<const float>(v));
        break;
    }
    case 1: {
        std::vector<int32_t> v(in.byte() % 12);
        for (int32_t& i : v) i = in.i32() % 64;
        (void)p.set_uniform(in.name(), std::span<const int32_t>(v));
        break;
    }
    case 2: (void)gl.bind_texture(in.i32() % 20, texture(in)); break;
    case 3: scramble_state(in, gl); break;
    case 4: {
        int w = int(in.count(64)), h = int(in.count(64));
        if (int64_t(w) * h > 64 * 64 && check_framebuffer_size(w, h)) break;  // accepted but too slow to draw
        auto created = Framebuffer::create(w, h, in.byte() & 1, in.i32() % 10);
        if (created) fb = std::make_unique<Framebuffer>(std::move(created.value()));
        break;
    }
    case 5: {
        auto prim = in.as_enum<Primitive>();
        uint32_t count = in.count(12);
        std::vector<VertexAttrib> attribs = attributes(in);
        std::vector<uint32_t> indices(in.byte() % 16);
        for (uint32_t& i : indices) i = in.count(12);
        ClearValues clear;
        if (in.byte() & 1) clear.color = glm::vec4(in.f32());
        if (in.byte() & 1) clear.stencil = in.i32();
        (void)draw(p, gl, *fb, clear, prim, attribs, count, indices);
        break;
    }
    case 6: (void)run_vertices(p, attributes(in), in.count(40), in.byte() & 1 ? &gl : nullptr); break;
    case 7: (void)run_fragments(p, attributes(in), in.count(40), in.byte() & 1 ? &gl : nullptr); break;
    case 8:
        p.exec.precision = in.as_enum<Precision>();
        p.exec.backend = in.as_enum<Backend>();
        p.exec.threads = in.byte() % 4;
        break;
    default: (void)apply_builtin_uniforms(p, gl); break;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Bytes in(data, size);
    const uint8_t pick = in.byte();
    // The JIT's compile (tens of ms) would dominate every input: the interpreter draws, and the
    // differential tests keep the backends equal.
    auto compiled = Program::compile({{"f.vert", kVertex[pick & 1]}}, {{"f.frag", kFragment[(pick >> 1) & 1]}});
    if (!compiled) __builtin_trap();  // the fixed programs compile
    Program p = std::move(compiled.value());
    p.exec.backend = Backend::Interp;
    p.exec.threads = 1;
    p.exec.max_instructions = 1u << 16;
    p.exec.max_draw_instructions = 1u << 20;
    if (pick & 4) {  // every member function of a moved-from Program answers too
        Program taken = std::move(p);
        (void)taken;
    }
    GLState gl;
    auto fb = std::make_unique<Framebuffer>(16, 16);
    for (int calls = 0; calls < 32 && !in.empty(); ++calls) call(in, p, gl, fb);
    (void)p.jit_compile_seconds();
    (void)p.dump_ir();
    (void)p.uniforms();
    return 0;
}
