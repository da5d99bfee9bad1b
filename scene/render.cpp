#include "glslrun/scene/render.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "runtime/program_state.h"
#include "runtime/mipmap_gpu.h"
#include "scene/scene_reader.h"
#include "scene/text_file.h"

namespace glslrun::scene {

const VertexAttrib* Mesh::find(std::string_view name) const {
    for (const VertexAttrib& a : attribs)
        if (a.name == name) return &a;
    return nullptr;
}

namespace {

// "arr[2]" and "s[1].f[0]" name an element of what uniforms() lists as
// "arr" and "s[1].f": drop a trailing subscript to find the declaration.
const UniformInfo* find_declaration(const std::vector<UniformInfo>& infos, std::string_view name) {
    for (int pass = 0; pass < 2; ++pass) {
        for (const UniformInfo& u : infos)
            if (u.name == name) return &u;
        if (name.empty() || name.back() != ']') break;
        name = name.substr(0, name.rfind('['));
    }
    return nullptr;
}

bool is_integer_type(std::string_view type) {
    return type.starts_with("int") || type.starts_with("ivec") || type.starts_with("bool") ||
           type.starts_with("bvec") || type.starts_with("sampler");
}

// What follows "has no active uniform 'x'": the closest non-built-in name
// when the user probably misspelt it, else the usual causes.
std::string no_uniform_hint(const std::vector<const std::vector<UniformInfo>*>& lists, std::string_view name) {
    std::vector<std::string_view> names;
    for (const auto* list : lists)
        for (const UniformInfo& u : *list)
            if (!u.builtin) names.push_back(u.name);
    std::string best = detail::closest(name, names);
    if (!best.empty()) return fmt::format("; did you mean '{}'?", best);
    return " (is it declared and used by a shader?)";
}

Error error_at(const SourceLoc& where, std::string message) {
    return Error(std::move(message), where.file, where.line);
}

Status apply_one(Program& program, const std::vector<UniformInfo>& infos, const UniformSetting& s) {
    const UniformInfo* info = find_declaration(infos, s.name);
    if (!info)
        return error_at(s.where, fmt::format("the program has no active uniform '{}'{}", s.name,
                                             no_uniform_hint({&infos}, s.name)));
    Status st = Ok{};
    if (is_integer_type(info->type)) {
        if (!s.integral && info->type.starts_with("sampler"))
            return error_at(s.where, fmt::format("uniform '{}' is a {}: its value is a texture unit, an "
                                                 "integer (write 0, not 0.0)", s.name, info->type));
        if (!s.integral)
            return error_at(s.where, fmt::format("uniform '{}' is a {}: its values must be "
                                                 "integers or booleans", s.name, info->type));
        std::vector<int32_t> ints;
        for (double v : s.values) {
            if (std::abs(v) > 2147483647.0)
                return error_at(s.where, fmt::format("uniform '{}': {} does not fit in an int", s.name, v));
            ints.push_back(int32_t(v));
        }
        st = program.set_uniform(s.name, ints);
    } else {
        std::vector<float> floats(s.values.begin(), s.values.end());
        st = program.set_uniform(s.name, floats);
    }
    if (!st) {
        // The declaration beside set_uniform's count: what the entry must give.
        std::string why = st.error().diagnostics.empty() ? "rejected" : st.error().diagnostics[0].message;
        return error_at(s.where, fmt::format("{} (the program declares 'uniform {} {}{}')", why, info->type,
                                             info->name, info->array_size > 1 ? fmt::format("[{}]", info->array_size)
                                                                              : ""));
    }
    return Ok{};
}

}  // namespace

int color_buffers(const Scene& scene) {
    int n = scene.gl.draw_buffers;
    for (const Object& o : scene.objects)
        if (o.state) n = std::max(n, o.state->draw_buffers);
    for (const Pass& p : scene.passes) {
        if (p.target >= 0) continue;  // draws into a render target's own colour buffers
        n = std::max(n, p.state.draw_buffers);
        for (const auto& state : p.object_states)
            if (state) n = std::max(n, state->draw_buffers);
    }
    return n;
}

std::string color_buffer_path(const std::string& output, int buffer) {
    if (buffer == 0) return output;
    std::filesystem::path p(output);
    return (p.parent_path() / fmt::format("{}.{}{}", p.stem().string(), buffer, p.extension().string())).string();
}

namespace {

Status apply_settings(Program& program, const std::vector<UniformInfo>& infos,
                      const std::vector<UniformSetting>& settings, bool skip_undeclared) {
    for (const UniformSetting& s : settings) {
        if (skip_undeclared && !find_declaration(infos, s.name)) continue;
        if (Status st = apply_one(program, infos, s); !st) return st;
    }
    return Ok{};
}

// The texture a setting binds under `rounding`: with the GPU's rounding a
// GL_GENERATE_MIPMAP texture's levels are generated again as NVIDIA's driver
// makes them (rt::generate_gpu_mipmaps), into a copy.
std::shared_ptr<const Texture> gpu_texture_for(const TextureSetting& t, ColorRounding rounding) {
    if (rounding != ColorRounding::Gpu || !t.generate_mipmap || !t.texture) return t.texture;
    auto copy = std::make_shared<Texture>(*t.texture);
    if (!rt::generate_gpu_mipmaps(*copy)) return t.texture;
    return copy;
}

}  // namespace

Status apply_uniforms(Program& program, const std::vector<UniformSetting>& settings, bool skip_undeclared) {
    if (settings.empty()) return Ok{};
    return apply_settings(program, program.uniforms(), settings, skip_undeclared);
}

Result<GLState> bind_scene_textures(const Scene& scene, ColorRounding rounding) {
    GLState bound = scene.gl;
    for (const TextureSetting& t : scene.textures)
        if (Status st = bound.bind_texture(t.unit, gpu_texture_for(t, rounding)); !st) return st.error();
    return bound;
}

// The GPU-mipmapped copies by source texture (holding the source, so that
// its address is not reused while it is a key).
struct ScenePrograms::GpuMipmaps {
    std::mutex mutex;
    std::map<const Texture*, std::pair<std::shared_ptr<const Texture>, std::shared_ptr<const Texture>>> copies;
};

std::shared_ptr<const Texture> ScenePrograms::texture_for(const TextureSetting& t, ColorRounding rounding) const {
    if (rounding != ColorRounding::Gpu || !t.generate_mipmap || !t.texture) return t.texture;
    std::lock_guard lock(gpu_mipmaps_->mutex);
    auto& slot = gpu_mipmaps_->copies[t.texture.get()];
    if (!slot.first) slot = {t.texture, gpu_texture_for(t, rounding)};
    return slot.second;
}

GLState object_gl_state(const Scene& scene, const GLState& bound, const Object& object, const Pass* pass) {
    const GLState* state = object.state ? &*object.state : &bound;
    if (pass) {
        const auto& own = pass->object_states[size_t(&object - scene.objects.data())];
        state = own ? &*own : &pass->state;
    }
    GLState gl = *state;
    gl.texture_units = bound.texture_units;
    gl.modelview = (pass && pass->view ? *pass->view : scene.view) * object.model;
    // A pass with a camera of its own keeps its projection; the others draw with the scene's.
    if (!(pass && pass->own_projection)) gl.projection = scene.projection;
    gl.lights = eye_space_lights(scene);
    // The texgen planes and environment colours that shaders read as built-ins.
    for (size_t unit = 0; unit < 8; ++unit) {
        gl.texture_env_color[unit] = scene.fixed.texture_env[unit].color;
        for (size_t c = 0; c < 4; ++c) {
            gl.object_planes[unit][c] = scene.fixed.texture_gen[unit][c].object_plane;
            gl.eye_planes[unit][c] = scene.fixed.texture_gen[unit][c].eye_plane;
        }
    }
    if (object.front_material) gl.front_material = *object.front_material;
    if (object.back_material) gl.back_material = *object.back_material;
    if (object.color) gl.current_color = *object.color;
    return gl;
}

// scene/ffp_programs.cpp
std::shared_ptr<FixedFunctionPrograms> make_fixed_function_programs(const CompileOptions& options);
Result<Program*> fixed_pass_program(const std::shared_ptr<FixedFunctionPrograms>& cache, const Scene& scene,
                                    const Pass& pass);

namespace {

// The scene's, objects' and passes' uniform entries that no program they go
// to has as an active uniform: GL ignores glUniform at location -1, so they
// are warnings (with the nearest name the programs have), not errors. One
// with no line, from the command line (--uniform) or code (Python's
// uniforms=), was typed for this render: an error.
Result<std::vector<Diagnostic>> unused_uniform_warnings(const ScenePrograms& programs, const Scene& scene) {
    std::vector<std::vector<UniformInfo>> infos;
    for (size_t i = 0; i < programs.size(); ++i) infos.push_back(programs.of_pass(i).uniforms());
    std::vector<Diagnostic> warnings;
    auto check = [&](const std::vector<UniformSetting>& settings, std::optional<size_t> pass) -> Status {
        std::vector<const std::vector<UniformInfo>*> lists;
        for (size_t i = 0; i < infos.size(); ++i)
            if (!pass || *pass == i) lists.push_back(&infos[i]);
        for (const UniformSetting& s : settings) {
            bool found = false;
            for (const auto* list : lists) found = found || find_declaration(*list, s.name);
            if (found) continue;
            const bool all_fixed = !scene.passes.empty() && std::all_of(scene.passes.begin(), scene.passes.end(),
                                                                         [](const Pass& p) { return p.fixed_function; });
            const std::string hint =
                all_fixed ? " (every draw is GL's fixed function, which has no uniforms of its own)"
                          : no_uniform_hint(lists, s.name);
            const std::string missing =
                pass ? fmt::format("pass '{}': its program has no active uniform '{}'", scene.passes[*pass].name,
                                   s.name)
                : lists.size() > 1 ? fmt::format("no pass's program has an active uniform '{}'", s.name)
                                   : fmt::format("the program has no active uniform '{}'", s.name);
            if (s.where.line == 0) return error_at(s.where, missing + hint);  // typed for this render
            warnings.push_back(Diagnostic{s.where.file, s.where.line,
                                          missing + ": the entry is ignored, as GL ignores glUniform at location -1" +
                                              hint,
                                          true});
        }
        return Ok{};
    };
    if (Status st = check(scene.uniforms, std::nullopt); !st) return st.error();
    for (const Object& o : scene.objects)
        if (Status st = check(o.uniforms, std::nullopt); !st) return st.error();
    for (size_t i = 0; i < scene.passes.size(); ++i)
        if (Status st = check(scene.passes[i].uniforms, i); !st) return st.error();
    return warnings;
}

}  // namespace

Result<ScenePrograms> ScenePrograms::compile(Program& main, const Scene& scene) {
    return compile(main, scene, state_of(main).options);
}

Result<ScenePrograms> ScenePrograms::compile(Program& main, const Scene& scene, const CompileOptions& options) {
    ScenePrograms programs;
    programs.fixed_ = make_fixed_function_programs(options);
    programs.gpu_mipmaps_ = std::make_shared<GpuMipmaps>();
    if (scene.passes.empty()) programs.by_pass_.push_back(&main);
    for (const Pass& pass : scene.passes) {
        if (pass.fixed_function) {
            auto fixed = fixed_pass_program(programs.fixed_, scene, pass);
            if (!fixed) {
                Error e(fmt::format("pass '{}': its fixed-function program does not compile", pass.name),
                        pass.where.file, pass.where.line);
                for (const Diagnostic& d : fixed.error().diagnostics) e.diagnostics.push_back(d);
                return e;
            }
            (*fixed)->exec = main.exec;
            programs.by_pass_.push_back(*fixed);
            continue;
        }
        if (pass.vertex.empty() && pass.fragment.empty()) {
            programs.by_pass_.push_back(&main);
            continue;
        }
        auto program = Program::compile(pass.vertex, pass.fragment, options);
        if (!program) {
            Error e(fmt::format("pass '{}': its program does not compile", pass.name), pass.where.file,
                    pass.where.line);
            for (const Diagnostic& d : program.error().diagnostics) e.diagnostics.push_back(d);
            return e;
        }
        program->exec = main.exec;
        programs.own_.push_back(std::make_shared<Program>(std::move(*program)));
        programs.by_pass_.push_back(programs.own_.back().get());
    }
    auto warnings = unused_uniform_warnings(programs, scene);
    if (!warnings) return warnings.error();
    programs.warnings_ = std::move(*warnings);
    return programs;
}

namespace {

// The mesh's arrays, and for each [current] value the mesh has no array of,
// that value at every vertex: what GL's current attribute gives the shader.
std::vector<VertexAttrib> attribs_with_current(const Scene& scene, const Mesh& m) {
    std::vector<VertexAttrib> all = m.attribs;
    size_t vertices = m.vertex_count;
    for (const VertexAttrib& a : m.attribs) vertices = std::max(vertices, a.data.size() / std::max(a.components, 1u));
    for (const CurrentAttribute& c : scene.current_attributes) {
        if (m.find(c.name)) continue;
        VertexAttrib a{c.name, 4, {}};
        a.data.reserve(vertices * 4);
        for (size_t v = 0; v < vertices; ++v) a.data.insert(a.data.end(), {c.value.x, c.value.y, c.value.z, c.value.w});
        all.push_back(std::move(a));
    }
    return all;
}

// One pass's draws (the scene's one pass when `pass` is null); the first
// draw takes `pending` (and empties it).
Result<DrawStats> draw_pass(const ScenePrograms& programs, size_t index, const Scene& scene, GLState& bound,
                            const Pass* pass, Framebuffer& fb, ClearValues& pending) {
    Program& program = programs.of_pass(index);
    // An entry that no program uses is ignored, as GL ignores glUniform at location -1
    // (ScenePrograms::warnings names it); each program takes the entries it has.
    const bool lenient = true;
    if (Status st = apply_uniforms(program, scene.uniforms, lenient); !st) return st.error();
    if (pass)
        if (Status st = apply_uniforms(program, pass->uniforms, lenient); !st) return st.error();
    DrawStats total;
    // The program's uniforms, listed once for all its objects: a list of
    // strings made and freed per object was most of a small draw's CPU time
    // outside the rasterizer (bench/corpus/many_draws).
    std::optional<std::vector<UniformInfo>> infos;
    auto draw_object = [&](const Object& object) -> Status {
        // glBindTexture: context state, so it stays for the objects after this one.
        for (const TextureSetting& t : object.textures)
            if (Status st = bound.bind_texture(t.unit, programs.texture_for(t, fb.rounding)); !st) return st;
        GLState gl = object_gl_state(scene, bound, object, pass);
        if (!object.uniforms.empty()) {
            if (!infos) infos = program.uniforms();
            if (Status st = apply_settings(program, *infos, object.uniforms, lenient); !st) return st;
        }
        const Mesh& m = object.mesh;
        std::vector<VertexAttrib> with_current;
        if (!scene.current_attributes.empty()) with_current = attribs_with_current(scene, m);
        // The first draw clears, in its tiles on the workers (it clears even when it fails).
        auto drawn = programs.for_draw(index, scene, gl);
        if (!drawn) return drawn.error();
        auto stats = draw(**drawn, gl, fb, std::exchange(pending, {}), m.primitive,
                          with_current.empty() ? m.attribs : with_current, m.vertex_count, m.indices);
        if (!stats) return stats.error();
        total += *stats;
        return Ok{};
    };
    if (!pass)
        for (const Object& object : scene.objects)
            if (Status st = draw_object(object); !st) return st.error();
    if (pass)
        for (size_t i : pass->objects)
            if (Status st = draw_object(scene.objects[i]); !st) return st.error();
    return total;
}

// scene.gl's modelview, projection and lights are copies of view, projection
// and lights (load_scene fills them in); draws take the originals. A copy set
// to something else would be ignored: refuse it instead.
Status check_gl_copies(const Scene& scene) {
    const GLState defaults;
    auto problem = [](const char* copy, const char* source) {
        return Error(fmt::format("scene.gl.{} differs from scene.{}, which rendering uses: set scene.{} (and "
                                 "leave scene.gl.{} at GL's default, or call derive_eye_space_lights())",
                                 copy, source, source, copy));
    };
    if (scene.gl.modelview != defaults.modelview && scene.gl.modelview != scene.view)
        return problem("modelview", "view");
    if (scene.gl.projection != defaults.projection && scene.gl.projection != scene.projection)
        return problem("projection", "projection");
    std::array<LightState, 8> eye = eye_space_lights(scene);
    auto same = [](const LightState& a, const LightState& b) {
        return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
               a.position == b.position && a.spot_direction == b.spot_direction &&
               a.spot_exponent == b.spot_exponent && a.spot_cutoff == b.spot_cutoff &&
               a.constant_attenuation == b.constant_attenuation && a.linear_attenuation == b.linear_attenuation &&
               a.quadratic_attenuation == b.quadratic_attenuation;
    };
    for (size_t i = 0; i < eye.size(); ++i)
        if (!same(scene.gl.lights[i], defaults.lights[i]) && !same(scene.gl.lights[i], eye[i]))
            return problem(fmt::format("lights[{}]", i).c_str(), fmt::format("lights[{}]", i).c_str());
    return Ok{};
}

// The render targets' framebuffers, as glref's FBOs start: colour (0, 0, 0, 0),
// depth 1, stencil 0; RGBA8 colours stored as the output's are (`rounding`),
// float ones as floats or halves.
Result<std::vector<Framebuffer>> make_targets(const Scene& scene, ColorRounding rounding) {
    std::vector<Framebuffer> targets;
    for (const RenderTarget& t : scene.targets) {
        auto fb = Framebuffer::create(t.width, t.height, t.format != TextureFormat::RGBA8, t.color_buffers);
        if (!fb) return fb.error();
        fb->rounding = rounding;
        fb->half_float = t.format == TextureFormat::RGBA16F;
        fb->clear_color(glm::vec4(0));
        fb->clear_depth(1);
        fb->clear_stencil(0);
        targets.push_back(std::move(*fb));
    }
    return targets;
}

// What a pass drew into target `index` becomes the texels of the textures
// that sample it (an FBO's attachment is that texture). Depth is stored as a
// 24-bit depth buffer stores it (GL_DEPTH24_STENCIL8), as GL would sample it.
// `live` holds each target texture's current texels (by index into
// scene.textures); a unit an object has bound another texture to keeps it.
Status refresh_target_textures(const Scene& scene, int index, const Framebuffer& fb, GLState& bound,
                               std::vector<std::shared_ptr<const Texture>>& live) {
    for (size_t i = 0; i < scene.textures.size(); ++i) {
        const TextureSetting& setting = scene.textures[i];
        if (setting.render_target != index) continue;
        TextureImage image{fb.width, fb.height, 1, {}};
        image.texels.reserve(size_t(fb.width) * size_t(fb.height));
        constexpr double kMax24 = double((1 << 24) - 1);
        for (int y = 0; y < fb.height; ++y)
            for (int x = 0; x < fb.width; ++x) {
                if (setting.attachment >= 0) {
                    image.texels.push_back(fb.pixel(x, y, setting.attachment));
                    continue;
                }
                double d = std::clamp(double(fb.depth[size_t(y) * size_t(fb.width) + size_t(x)]), 0.0, 1.0);
                image.texels.push_back(glm::vec4(float(std::nearbyint(d * kMax24) / kMax24), 0, 0, 1));
            }
        auto texture = Texture::create(TextureTarget::Tex2D, {std::move(image)}, setting.texture->format());
        if (!texture) return texture.error();
        texture->sampler = setting.texture->sampler;
        auto made = std::make_shared<const Texture>(std::move(*texture));
        if (bound.texture_units[size_t(setting.unit)].bound[size_t(TextureTarget::Tex2D)] == live[i])
            if (Status st = bound.bind_texture(setting.unit, made); !st) return st;
        live[i] = std::move(made);
    }
    return Ok{};
}

// Leftover clears of a pass that drew nothing still happen.
void flush_clear(Framebuffer& fb, ClearValues& pending) {
    if (pending.color) fb.clear_color(*pending.color);
    if (pending.depth) fb.clear_depth(*pending.depth);
    if (pending.stencil) fb.clear_stencil(*pending.stencil);
    pending = {};
}

// One render's instruction count (ExecOptions::render_instructions) on
// every pass's program for the render's draws, unless the caller already
// counts several renders as one (glslrun --frames).
class RenderCount {
public:
    explicit RenderCount(const ScenePrograms& programs) {
        for (size_t i = 0; i < programs.size(); ++i) {
            Program& p = programs.of_pass(i);
            if (p.exec.render_instructions) continue;  // the caller's, or ours through an earlier pass
            p.exec.render_instructions = &count_;
            counted_.push_back(&p);
        }
    }
    ~RenderCount() {
        for (Program* p : counted_) p->exec.render_instructions = nullptr;
    }
    RenderCount(const RenderCount&) = delete;
    RenderCount& operator=(const RenderCount&) = delete;

private:
    std::atomic<uint64_t> count_{0};
    std::vector<Program*> counted_;
};

Result<DrawStats> draw_passes(const ScenePrograms& programs, const Scene& scene, Framebuffer& fb,
                              ClearValues& pending) {
    RenderCount count(programs);
    if (Status st = check_gl_copies(scene); !st) return st.error();
    // glActiveTexture + glBindTexture per [textures.N], once: texture
    // bindings are context state that every object's draw sees.
    // (the scene's own textures through the programs' GPU-mipmapped copies)
    Result<GLState> bound = scene.gl;
    for (const TextureSetting& t : scene.textures)
        if (Status st = bound->bind_texture(t.unit, programs.texture_for(t, fb.rounding)); !st) return st.error();
    if (scene.passes.empty()) return draw_pass(programs, 0, scene, *bound, nullptr, fb, pending);
    auto targets = make_targets(scene, fb.rounding);
    if (!targets) return targets.error();
    std::vector<std::shared_ptr<const Texture>> live;
    for (const TextureSetting& t : scene.textures) live.push_back(t.texture);
    DrawStats total;
    for (size_t i = 0; i < scene.passes.size(); ++i) {
        const Pass& pass = scene.passes[i];
        // A pass's clear after the scene's: a full clear replaces an earlier one.
        ClearValues target_clear = pass.clear;
        ClearValues& clear = pass.target < 0 ? pending : target_clear;
        if (pass.clear.color) clear.color = pass.clear.color;
        if (pass.clear.depth) clear.depth = pass.clear.depth;
        if (pass.clear.stencil) clear.stencil = pass.clear.stencil;
        Framebuffer& into = pass.target < 0 ? fb : (*targets)[size_t(pass.target)];
        if (programs.before_pass) programs.before_pass(i);
        auto stats = draw_pass(programs, i, scene, *bound, &pass, into, clear);
        if (pass.target >= 0) flush_clear(into, target_clear);
        if (!stats) return stats.error();
        total += *stats;
        if (pass.target >= 0)
            if (Status st = refresh_target_textures(scene, pass.target, into, *bound, live); !st) return st.error();
    }
    return total;
}

}  // namespace

Result<DrawStats> draw_scene_objects(const ScenePrograms& programs, const Scene& scene, Framebuffer& fb,
                                     const ClearValues& clear) {
    // Scenes store colours as their precision mode's GL would (Fast: the GPU's rule).
    fb.rounding = color_rounding_for(programs.of_pass(0).exec.precision);
    ClearValues pending = clear;
    auto result = draw_passes(programs, scene, fb, pending);
    // No object, or an error before the first draw: the clear still happens.
    flush_clear(fb, pending);
    return result;
}

Result<DrawStats> draw_scene_objects(Program& program, const Scene& scene, Framebuffer& fb,
                                     const ClearValues& clear) {
    auto programs = ScenePrograms::compile(program, scene);
    if (!programs) return programs.error();
    return draw_scene_objects(*programs, scene, fb, clear);
}

Result<DrawStats> render_scene(const ScenePrograms& programs, const Scene& scene, Framebuffer& fb) {
    return draw_scene_objects(programs, scene, fb,
                              ClearValues{scene.clear_color, scene.clear_depth, scene.clear_stencil});
}

Result<DrawStats> render_scene(Program& program, const Scene& scene, Framebuffer& fb) {
    return draw_scene_objects(program, scene, fb, ClearValues{scene.clear_color, scene.clear_depth, scene.clear_stencil});
}

Result<Image> render_image(Program& program, const Scene& scene) {
    auto fb = Framebuffer::create(scene.width, scene.height, false, color_buffers(scene));
    if (!fb) return fb.error();
    auto stats = render_scene(program, scene, *fb);
    if (!stats) return stats.error();
    return read_framebuffer(*fb);
}

Result<std::vector<ShaderSource>> read_shader_files(const std::vector<std::string>& paths) {
    std::vector<ShaderSource> sources;
    for (const std::string& path : paths) {
        auto text = read_text_file(path, "shader");
        if (!text) return text.error();
        sources.push_back({path, std::move(*text)});
    }
    return sources;
}

Result<Program> compile_files(const std::vector<std::string>& vertex_paths,
                              const std::vector<std::string>& fragment_paths, const CompileOptions& options) {
    auto vertex = read_shader_files(vertex_paths);
    if (!vertex) return vertex.error();
    auto fragment = read_shader_files(fragment_paths);
    if (!fragment) return fragment.error();
    return Program::compile(*vertex, *fragment, options);
}

Result<Image> render_files(const std::string& vertex_path, const std::string& fragment_path,
                           const std::string& scene_path, const ExecOptions& exec) {
    auto scene = load_scene(scene_path);
    if (!scene) return scene.error();
    auto program = compile_files({vertex_path}, {fragment_path});
    if (!program) return program.error();
    program->exec = exec;
    return render_image(*program, *scene);
}

}  // namespace glslrun::scene
