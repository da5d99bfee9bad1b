// The programs of draws with GL's fixed function for a stage: the stage
// generated from the draw's state (scene/ffp.h) linked with the pass's own
// shaders, compiled once per distinct generated source, as Mesa keeps its
// fixed-function programs per state key.
#include <algorithm>
#include <cstring>
#include <map>

#include <fmt/format.h>

#include "glslrun/scene/render.h"
#include "ir/ir.h"
#include "runtime/program_state.h"
#include "scene/ffp.h"

namespace glslrun::scene {

class FixedFunctionPrograms {
public:
    explicit FixedFunctionPrograms(CompileOptions options) : options_(std::move(options)) {}
    // The program of `base`'s shaders (none for a fixed pass) with the generated stages.
    // `generated_vertex`: the vertex stage is GL's fixed function (the rasterizer treats its point size so).
    Result<Program*> get(const Program* base, const std::vector<ShaderSource>& vertex,
                         const std::vector<ShaderSource>& fragment, const CompileOptions& options, uint8_t samplers,
                         bool generated_vertex);
    const CompileOptions& options() const { return options_; }

private:
    CompileOptions options_;
    std::map<std::string, std::shared_ptr<Program>> programs_;
};

namespace {

// gl_TexCoord[i] the user's fragment shader reads (all of them where it indexes the array).
uint8_t texcoords_read(const Program& program) {
    uint8_t units = 0;
    for (const ir::Binding& b : state_of(program).ir.fragment.inputs) {
        if (b.name == "gl_TexCoord") return 0xff;
        if (b.name.starts_with("gl_TexCoord[") && b.name.size() > 12 && b.name[12] >= '0' && b.name[12] <= '7')
            units |= uint8_t(1u << (b.name[12] - '0'));
    }
    return units;
}

// glUniform values of `from`'s own uniforms on `to`, where `to` has them:
// the draw's program holds the uniforms the scene set on the pass's program.
Status copy_user_uniforms(const Program& from, Program& to) {
    const Program::State& src = state_of(from);
    for (const ir::Uniform& u : state_of(to).ir.uniforms) {
        if (u.builtin) continue;
        uint32_t element = 0;
        const ir::Uniform* s = ir::find_uniform(src.ir, u.name, &element);
        if (!s || element != 0 || s->type.components() != u.type.components() || s->type.kind != u.type.kind) continue;
        size_t words = size_t(u.type.components()) * std::min(u.array_size, s->array_size);
        const uint32_t* w = src.uniforms.data() + s->slot;
        Status st = Ok{};
        if (u.type.kind == ir::Kind::F32 && !u.type.is_sampler) {
            std::vector<float> values(words);
            std::memcpy(values.data(), w, words * sizeof(float));
            st = to.set_uniform(u.name, values);
        } else {
            st = to.set_uniform(u.name, std::vector<int32_t>(w, w + words));
        }
        if (!st) return st;
    }
    return Ok{};
}

std::string stage_text(const std::vector<ShaderSource>& sources) {
    std::string text;
    for (const ShaderSource& s : sources) text += s.name + "\n" + s.text + "\n";
    return text;
}

}  // namespace

Result<Program*> FixedFunctionPrograms::get(const Program* base, const std::vector<ShaderSource>& vertex,
                                            const std::vector<ShaderSource>& fragment, const CompileOptions& options,
                                            uint8_t samplers, bool generated_vertex) {
    std::string key =
        fmt::format("{}\n{}\x01{}", static_cast<const void*>(base), stage_text(vertex), stage_text(fragment));
    auto found = programs_.find(key);
    if (found != programs_.end()) return found->second.get();
    auto program = Program::compile(vertex, fragment, options);
    if (!program) return program.error();
    state_of(*program).ir.fixed_function_vertex = generated_vertex;
    // Both stages' sources, the generated one too: the shader debugger compiles its twin from them.
    state_of(*program).vertex_sources = vertex;
    state_of(*program).fragment_sources = fragment;
    // A unit whose texel no combiner reads (DECAL of a luminance texture) has no active sampler.
    for (int u = 0; u < 8; ++u)
        if ((samplers >> u & 1) && program->has_uniform(ffp::sampler_uniform(u)))
            if (Status st = program->set_uniform(ffp::sampler_uniform(u), std::vector<int32_t>{u}); !st)
                return st.error();
    auto made = std::make_shared<Program>(std::move(*program));
    programs_.emplace(std::move(key), made);
    return made.get();
}

Result<Program*> ScenePrograms::for_draw(size_t pass, const Scene& scene, GLState& gl) const {
    Program& base = of_pass(pass);
    const Program::State& st = state_of(base);
    const bool fixed = !scene.passes.empty() && scene.passes[pass].fixed_function;
    const bool gen_vs = fixed || (st.vertex_sources.empty() && !st.fragment_sources.empty());
    const bool gen_fs = fixed || (st.fragment_sources.empty() && !st.vertex_sources.empty());
    if (!gen_vs && !gen_fs) return &base;
    ffp::VertexNeeds needs;
    needs.texcoords = gen_fs ? ffp::fragment_units(scene, gl) : texcoords_read(base);
    const uint8_t samplers = gen_fs ? ffp::fragment_units(scene, gl) : 0;
    std::vector<ShaderSource> vertex = st.vertex_sources, fragment = st.fragment_sources;
    if (gen_vs) vertex = {{ffp::kVertexStageName, ffp::vertex_source(scene, gl, needs)}};
    if (gen_fs) fragment = {{ffp::kFragmentStageName, ffp::fragment_source(scene, gl)}};
    auto program = fixed_->get(fixed ? nullptr : &base, vertex, fragment, fixed ? fixed_->options() : st.options,
                               samplers, gen_vs);
    if (!program) {
        std::string own = gen_vs ? (st.fragment_sources.empty() ? "" : st.fragment_sources[0].name)
                                 : st.vertex_sources[0].name;
        Error e(fixed ? "the fixed-function program generated for this draw does not compile"
                      : fmt::format("'{}' does not link with the fixed-function {} stage generated for this draw "
                                    "(it writes gl_Position, gl_FrontColor, gl_BackColor, the secondary colours, "
                                    "gl_TexCoord[] and gl_FogFragCoord)",
                                    own, gen_vs ? "vertex" : "fragment"));
        for (const Diagnostic& d : program.error().diagnostics) e.diagnostics.push_back(d);
        return e;
    }
    Program& drawn = **program;
    if (!fixed)
        if (Status copied = copy_user_uniforms(base, drawn); !copied) return copied.error();
    drawn.exec = base.exec;
    state_of(drawn).probe = st.probe;
    state_of(drawn).undef = st.undef;
    state_of(drawn).fast_ops = st.fast_ops;
    // GL's two-sided lighting picks gl_BackColor for back faces, as
    // GL_VERTEX_PROGRAM_TWO_SIDE does for a vertex shader.
    if (gen_vs) gl.vertex_program_two_side = ffp::two_sided_lighting(scene, gl);
    return &drawn;
}

// A `program = "fixed"` pass's program: the stages generated for the pass's state.
Result<Program*> fixed_pass_program(const std::shared_ptr<FixedFunctionPrograms>& cache, const Scene& scene,
                                    const Pass& pass) {
    auto bound = bind_scene_textures(scene);
    if (!bound) return bound.error();
    GLState gl = pass.state;
    gl.texture_units = bound->texture_units;
    uint8_t units = ffp::fragment_units(scene, gl);
    ffp::VertexNeeds needs{units};
    return cache->get(nullptr, {{ffp::kVertexStageName, ffp::vertex_source(scene, gl, needs)}},
                      {{ffp::kFragmentStageName, ffp::fragment_source(scene, gl)}}, cache->options(), units,
                      true);
}

std::shared_ptr<FixedFunctionPrograms> make_fixed_function_programs(const CompileOptions& options) {
    return std::make_shared<FixedFunctionPrograms>(options);
}

void use_fixed_function(Scene& scene) {
    if (scene.passes.empty()) {
        Pass pass;
        pass.name = "fixed function";
        pass.where = {scene.path, 0};
        pass.state = scene.gl;
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            pass.objects.push_back(i);
            pass.object_states.push_back(scene.objects[i].state);
        }
        scene.passes.push_back(std::move(pass));
    }
    for (Pass& pass : scene.passes)
        if (pass.vertex.empty() && pass.fragment.empty()) pass.fixed_function = true;
}

std::string fixed_function_warning(const Scene& scene) {
    const FixedFunction& f = scene.fixed;
    bool state = f.lighting || f.fog || f.color_sum || f.separate_specular;
    for (int u = 0; u < 8; ++u) {
        state = state || f.texture_env[size_t(u)].enabled;
        for (const TexGen& g : f.texture_gen[size_t(u)]) state = state || g.mode != TexGenMode::Off;
    }
    for (const Object& o : scene.objects) {
        state = state || o.color.has_value();
        for (const VertexAttrib& a : o.mesh.attribs) state = state || a.name == "gl_Color";
    }
    for (const CurrentAttribute& c : scene.current_attributes) state = state || c.name == "gl_Color";
    for (const Pass& p : scene.passes) state = state || p.fixed_function;
    if (state) return {};
    return fmt::format("warning: {}: no shaders were given, and the scene sets no fixed-function state, so GL's "
                       "fixed function draws every object unlit in white: give the program's shaders (glslrun "
                       "a.vert a.frag scene.toml), or the state ([fixed_function] lighting, [texture_env.N], "
                       "[fog], colours: docs/scene-format.md, \"Fixed function\")",
                       scene.path);
}

Result<Program> unused_main_program() {
    return Program::compile({{"(fixed function)", "void main() { gl_Position = ftransform(); }\n"}}, {});
}

}  // namespace glslrun::scene
