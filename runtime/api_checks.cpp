#include "runtime/api_checks.h"

#include <cmath>

#include <fmt/format.h>

namespace glslrun::rt {

namespace {

Error invalid_enum(const char* what, uint64_t value) {
    return Error(fmt::format("{} {} is not one of its enum's values (GL_INVALID_ENUM)", what, value));
}

bool sampler_in_range(const SamplerState& s) {
    auto wrap_ok = [](TextureWrap w) { return enum_in_range(w, TextureWrap::MirroredRepeat); };
    return enum_in_range(s.min_filter, TextureFilter::LinearMipmapLinear) &&
           enum_in_range(s.mag_filter, TextureFilter::LinearMipmapLinear) && wrap_ok(s.wrap_s) && wrap_ok(s.wrap_t) &&
           wrap_ok(s.wrap_r) && enum_in_range(s.compare_func, CompareFunc::Always) &&
           enum_in_range(s.depth_mode, DepthTextureMode::Alpha);
}

Status check_stencil(const StencilFace& face) {
    if (!enum_in_range(face.func, CompareFunc::Always)) return invalid_enum("stencil function", uint64_t(face.func));
    for (StencilOp op : {face.fail, face.depth_fail, face.depth_pass})
        if (!enum_in_range(op, StencilOp::DecrWrap)) return invalid_enum("stencil operation", uint64_t(op));
    return Ok{};
}

Status check_blend(const BlendState& b) {
    for (BlendFactor f : {b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha})
        if (!enum_in_range(f, BlendFactor::SrcAlphaSaturate)) return invalid_enum("blend factor", uint64_t(f));
    for (BlendEquation e : {b.equation_rgb, b.equation_alpha})
        if (!enum_in_range(e, BlendEquation::Max)) return invalid_enum("blend equation", uint64_t(e));
    return Ok{};
}

}  // namespace

Status check_exec_options(const ExecOptions& exec) {
    if (!enum_in_range(exec.precision, Precision::Fast))
        return Error(fmt::format("ExecOptions::precision {} is not Reference, Precise or Fast", int(exec.precision)));
    if (!enum_in_range(exec.backend, Backend::Auto))
        return Error(fmt::format("ExecOptions::backend {} is not Interp, Jit or Auto", int(exec.backend)));
    return Ok{};
}

Status check_texture_enums(TextureTarget target, TextureFormat format) {
    if (!enum_in_range(target, TextureTarget::Tex2DArray))
        return Error(fmt::format("texture target {} is not Tex1D, Tex2D, Tex3D, Cube, Rect, Tex1DArray or "
                                 "Tex2DArray (GL_INVALID_ENUM)",
                                 int(target)));
    if (!enum_in_range(format, TextureFormat::RGBA16F))
        return Error(fmt::format("texture format {} is not RGBA8, RGBA32F, Depth or RGBA16F (GL_INVALID_ENUM)",
                                 int(format)));
    return Ok{};
}

Status check_gl_enums(const GLState& gl) {
    if (!enum_in_range(gl.depth_func, CompareFunc::Always))
        return Error(fmt::format("depth function {} is not a GL compare function (GL_INVALID_ENUM)", int(gl.depth_func)));
    for (PolygonMode mode : gl.polygon_mode)
        if (!enum_in_range(mode, PolygonMode::Fill))
            return Error(fmt::format("polygon mode {} is not GL_POINT, GL_LINE or GL_FILL (GL_INVALID_ENUM)", int(mode)));
    if (!enum_in_range(gl.alpha_func, CompareFunc::Always)) return invalid_enum("alpha function", uint64_t(gl.alpha_func));
    for (const StencilFace& face : gl.stencil)
        if (Status st = check_stencil(face); !st) return st;
    if (Status st = check_blend(gl.blend_state); !st) return st;
    if (!enum_in_range(gl.logic_op, LogicOp::Set)) return invalid_enum("logic op", uint64_t(gl.logic_op));
    for (const GLState::TextureUnit& unit : gl.texture_units)
        for (size_t target = 0; target < unit.bound.size(); ++target) {
            const auto& texture = unit.bound[target];
            if (!texture) continue;
            if (size_t(texture->target()) != target)
                return Error("a texture is bound in the slot of another target (GLState::TextureUnit::bound is "
                             "indexed by TextureTarget: bind_texture fills it)");
            if (!sampler_in_range(texture->sampler))
                return Error("a bound texture's sampler state holds a value outside its enum (GL_INVALID_ENUM)");
        }
    return Ok{};
}

Status check_path(std::string_view path) {
    size_t nul = path.find('\0');
    if (nul == std::string_view::npos) return Ok{};
    return Error(fmt::format("the path '{}' holds a NUL byte (at byte {}): no file name does", path.substr(0, nul), nul));
}

Error out_of_memory(const char* what) {
    return Error(fmt::format("out of memory in {}", what));
}

Status check_batch_size(uint64_t count, uint64_t words_per_element, const char* what) {
    if (count > kMaxBatchElements)
        return Error(fmt::format("{} {} are too many: at most {} ({}M) a call", count, what, kMaxBatchElements,
                                 kMaxBatchElements >> 20));
    if (count * words_per_element * 4 > kMaxBatchBytes)
        return Error(fmt::format("{} {} of {} values each need {} MiB of outputs: at most {} MiB a call", count, what,
                                 words_per_element, (count * words_per_element * 4) >> 20, kMaxBatchBytes >> 20));
    return Ok{};
}

}  // namespace glslrun::rt
