// `import glslrun`: compile programs, set uniforms, run vertex and fragment
// batches on numpy arrays (docs/library.md). Errors are glslrun.Error.
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "module.h"

namespace glslrun::python {
namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The declaration `name` sets: "arr[2]" is an element of "arr", "s[1].f" a leaf of its own.
const UniformInfo* find_declaration(const std::vector<UniformInfo>& infos, std::string name) {
    for (;;) {
        for (const UniformInfo& u : infos)
            if (u.name == name) return &u;
        if (name.empty() || name.back() != ']') return nullptr;
        name.erase(name.rfind('['));
    }
}

bool takes_floats(const std::string& type) {
    return type == "float" || type.starts_with("vec") || type.starts_with("mat");
}

bool all_whole(const py::array_t<double>& numbers) {
    for (py::ssize_t i = 0; i < numbers.size(); ++i)
        if (numbers.data()[i] != std::trunc(numbers.data()[i])) return false;
    return true;
}

// Records what set_uniform set, replacing an earlier setting of the same name.
void remember(PyProgram& program, scene::UniformSetting setting) {
    for (scene::UniformSetting& s : program.user_uniforms)
        if (s.name == setting.name) {
            s = std::move(setting);
            return;
        }
    program.user_uniforms.push_back(std::move(setting));
}

// Numbers, sequences or arrays of any shape, flattened in C order (a
// matrix's columns: pass m.T of a row-major numpy matrix, or a flat list
// column by column, as glUniformMatrix without transpose).
void set_uniform(PyProgram& program, const std::string& name, const py::object& value) {
    const UniformInfo* u = find_declaration(program.uniforms(), name);
    if (!u) throw ErrorException{Error("no active uniform named '" + name + "'")};
    // Counted before a copy: a broadcast view of 2^40 values costs nothing until copied.
    if (py::isinstance<py::array>(value) && py::reinterpret_borrow<py::array>(value).size() > py::ssize_t(1) << 16)
        throw ErrorException{Error("uniform '" + name + "': more values than any uniform holds (65536)")};
    py::array_t<double> numbers = uniform_numbers(name, value);
    const double* d = numbers.data();
    const size_t n = size_t(numbers.size());
    if (takes_floats(u->type)) {
        std::vector<float> floats(d, d + n);
        check(program.set_uniform(name, std::span<const float>(floats)));
    } else {
        // int, bool and sampler uniforms take whole numbers (Python bools too).
        std::vector<int32_t> ints(n);
        for (size_t i = 0; i < n; ++i) {
            if (!(d[i] >= INT32_MIN && d[i] <= INT32_MAX) || d[i] != double(int32_t(d[i]))) {
                std::string number = py::str(py::float_(d[i]));
                throw ErrorException{Error("uniform '" + name + "' is " + u->type + "; " + number +
                                           " is not a 32-bit integer")};
            }
            ints[i] = int32_t(d[i]);
        }
        check(program.set_uniform(name, std::span<const int32_t>(ints)));
    }
    remember(program, {name, std::vector<double>(d, d + n), all_whole(numbers), {"set_uniform", 0}});
}

std::string input_names(const std::vector<Program::Input>& inputs) {
    std::string out;
    for (const Program::Input& i : inputs) out += (out.empty() ? "" : ", ") + i.name;
    return out.empty() ? "nothing" : out;
}

// {name: array of shape (count,) or (count, components)} as attribute arrays;
// `count` from the arrays when not given (they must agree). Every name must
// be an input the stage reads: a misspelt one would silently read as zeros.
std::vector<VertexAttrib> to_attribs(const py::dict& arrays, uint32_t& count, const std::vector<Program::Input>& inputs,
                                     const std::string& stage) {
    std::vector<VertexAttrib> attribs;
    bool have_count = count != 0;
    for (auto [key, value] : arrays) {
        std::string name = py::cast<std::string>(key);
        auto input = std::find_if(inputs.begin(), inputs.end(), [&](const Program::Input& i) { return i.name == name; });
        if (input == inputs.end())
            throw py::value_error("the " + stage + " shader reads no input '" + name + "' (it reads " +
                                  input_names(inputs) + "; an input declared but never read is optimized away)");
        // The shape first, on the array as given: a broadcast view of 2^40
        // rows costs nothing until forcecast copies it.
        const std::string shape = "input '" + name + "' must be an array of shape (count,) or (count, components), "
                                  "count at most 2^26 and components 1..16";
        if (py::isinstance<py::array>(value)) {
            auto given = py::reinterpret_borrow<py::array>(value);
            if (given.ndim() < 1 || given.ndim() > 2 || given.shape(0) > py::ssize_t(1) << 26 ||
                (given.ndim() == 2 && (given.shape(1) < 1 || given.shape(1) > 16)))
                throw py::value_error(shape);
        }
        FloatArray a = FloatArray::ensure(value);
        if (!a && PyErr_ExceptionMatches(PyExc_MemoryError)) throw py::error_already_set();
        PyErr_Clear();
        if (!a || a.ndim() < 1 || a.ndim() > 2 || a.shape(0) > py::ssize_t(1) << 26 ||
            (a.ndim() == 2 && (a.shape(1) < 1 || a.shape(1) > 16)))
            throw py::value_error(shape);
        uint32_t rows = uint32_t(a.shape(0)), components = a.ndim() == 2 ? uint32_t(a.shape(1)) : 1;
        // As glVertexAttribPointer: 1..4 components (more only for a matrix's columns).
        uint32_t most = std::max(4u, input->components);
        if (components == 0 || components > most)
            throw py::value_error("input '" + name + "' has " + std::to_string(components) + " components; it takes 1.." +
                                  std::to_string(most));
        if (!have_count) count = rows, have_count = true;
        if (rows != count)
            throw py::value_error("input '" + name + "' has " + std::to_string(rows) + " rows; expected " +
                                  std::to_string(count));
        attribs.push_back({name, components, std::vector<float>(a.data(), a.data() + a.size())});
    }
    return attribs;
}

// Outputs as {name: array (count, components)}.
py::dict to_dict(const std::vector<ShaderOutput>& outputs, uint32_t count) {
    py::dict out;
    for (const ShaderOutput& o : outputs) {
        py::array_t<float> a({size_t(count), size_t(o.components)});
        std::copy(o.data.begin(), o.data.end(), a.mutable_data());
        out[py::str(o.name)] = std::move(a);
    }
    return out;
}

// The state one object of `scene` is drawn with (matrices, lights, material,
// textures, the scene's and the object's uniforms), applied to the program
// as a draw would apply it.
GLState object_state(PyProgram& program, const scene::Scene& scene, size_t object) {
    if (object >= scene.objects.size())
        throw py::index_error("the scene has " + std::to_string(scene.objects.size()) + " objects");
    const scene::Object& o = scene.objects[object];
    GLState gl = scene::object_gl_state(scene, take(scene::bind_scene_textures(scene)), o);
    // The scene's entries that the program does not declare are skipped, as render() skips them.
    const bool skip_undeclared = true;
    check(scene::apply_uniforms(program, scene.uniforms, skip_undeclared));
    check(scene::apply_uniforms(program, o.uniforms, skip_undeclared));
    check(scene::apply_uniforms(program, program.user_uniforms));  // the user's win, as on render()
    check(apply_builtin_uniforms(program, gl));
    return gl;
}

py::dict run_batch(PyProgram& program, const py::dict& inputs, uint32_t count, const scene::Scene* scene,
                   size_t object, bool vertices) {
    std::vector<VertexAttrib> attribs = to_attribs(inputs, count, program.inputs(vertices ? Stage::Vertex : Stage::Fragment),
                                                   vertices ? "vertex" : "fragment");
    if (count == 0) throw py::value_error("nothing to run: no inputs and no count");
    if (!vertices && count % 4 != 0)
        throw py::value_error("fragments run in 2x2 quads: the count (" + std::to_string(count) +
                              ") must be a multiple of 4");
    GLState gl;  // GL's defaults: identity matrices, ...
    if (scene)
        gl = object_state(program, *scene, object);
    else
        check(apply_builtin_uniforms(program, gl));
    std::vector<ShaderOutput> outputs;
    run_interruptibly(program.exec, 0, [&] {
        outputs = take(vertices ? run_vertices(program, attribs, count, &gl)
                                : run_fragments(program, attribs, count, &gl));
    });
    return to_dict(outputs, count);
}

std::vector<ShaderSource> sources(const py::object& texts, const char* default_name) {
    if (texts.is_none()) return {};  // the stage is GL's fixed function
    if (py::isinstance<py::str>(texts)) return {{default_name, py::cast<std::string>(texts)}};
    std::vector<ShaderSource> out;
    for (auto item : texts) {
        auto pair = py::cast<std::pair<std::string, std::string>>(item);
        out.push_back({pair.first, pair.second});
    }
    return out;
}

CompileOptions compile_options(int default_version, bool optimize, const std::vector<std::string>& include_dirs) {
    CompileOptions o;
    o.default_version = default_version;
    o.optimize = optimize;
    o.include_dirs = include_dirs;
    return o;
}

}  // namespace

std::vector<std::string> paths(const py::object& p) {
    if (p.is_none()) return {};  // the stage is GL's fixed function
    if (py::isinstance<py::str>(p)) return {py::cast<std::string>(p)};
    return py::cast<std::vector<std::string>>(p);
}

namespace {

// A program of one shader draws the other stage with GL's fixed function; one of none draws nothing.
void check_some_shader(const py::object& vertex, const py::object& fragment) {
    if (vertex.is_none() && fragment.is_none())
        throw py::value_error("a Program needs a vertex or a fragment shader (None for one stage: GL's fixed "
                              "function); a scene drawn with GL's fixed function alone: glslrun.render(\"scene.toml\")");
}

void bind_program(py::module_& m) {
    py::class_<PyProgram>(m, "Program", "A compiled vertex and fragment program.")
        .def_static(
            "compile",
            [](const py::object& vertex, const py::object& fragment, int default_version, bool optimize,
               const std::vector<std::string>& include_dirs) {
                check_some_shader(vertex, fragment);
                return PyProgram(take(Program::compile(sources(vertex, "shader.vert"), sources(fragment, "shader.frag"),
                                                       compile_options(default_version, optimize, include_dirs))));
            },
            py::arg("vertex"), py::arg("fragment"), py::arg("default_version") = 110, py::arg("optimize") = true,
            py::kw_only(), py::arg("include_dirs") = std::vector<std::string>{},
            "Compiles GLSL text: a string per stage, or a list of (name, text) pairs; None for a stage that GL's "
            "fixed function draws (generated from the scene at each render). `include_dirs`: where "
            "`#include` looks after the including source's own directory (as the command line's -I).")
        .def_static(
            "from_files",
            [](const py::object& vertex, const py::object& fragment, int default_version, bool optimize,
               const std::vector<std::string>& include_dirs) {
                check_some_shader(vertex, fragment);
                return PyProgram(take(scene::compile_files(paths(vertex), paths(fragment),
                                                           compile_options(default_version, optimize, include_dirs))));
            },
            py::arg("vertex"), py::arg("fragment"), py::arg("default_version") = 110, py::arg("optimize") = true,
            py::kw_only(), py::arg("include_dirs") = std::vector<std::string>{},
            "Compiles shader files: a path per stage, or a list of paths; None for a stage that GL's fixed "
            "function draws. `include_dirs`: as the command line's "
            "-I.")
        .def("set_uniform", &set_uniform, py::arg("name"), py::arg("value"),
             "Sets a uniform from a number, a sequence or a numpy array (glUniform semantics).")
        .def("has_uniform", &Program::has_uniform, py::arg("name"),
             "Whether the program has an active uniform `name` (\"u\", \"arr[2]\", \"s.f\").")
        .def_property_readonly(
            "uniforms",
            [](const PyProgram& p) {
                                   py::list out;
                                   for (const UniformInfo& u : p.uniforms())
                                       out.append(py::dict(py::arg("name") = u.name, py::arg("type") = u.type,
                                                           py::arg("array_size") = u.array_size,
                                                           py::arg("builtin") = u.builtin, py::arg("read") = u.read));
                                   return out;
                               },
            "The uniform declarations: dicts with name, type, array_size, builtin, read.")
        .def_property(
            "threads", [](const PyProgram& p) { return p.exec.threads; },
            [](PyProgram& p, unsigned n) { p.exec.threads = n; },
            "Worker threads for rendering (0: one per core); images do not depend on it.")
        .def_property(
            "precision", [](const PyProgram& p) { return std::string(precision_name(p.exec.precision)); },
            [](PyProgram& p, const std::string& name) { p.exec.precision = take(parse_precision(name)); },
            "How floats are evaluated: \"precise\" (fp32, the default), \"fast\" or \"reference\" (double).")
        .def_property(
            "backend", [](const PyProgram& p) { return std::string(backend_name(p.exec.backend)); },
            [](PyProgram& p, const std::string& name) { p.exec.backend = take(parse_backend(name)); },
            "Who runs the shaders: \"auto\" (the default: the LLVM JIT where built in), \"jit\" or \"interp\"; "
            "both give the same bits.")
        .def_property(
            "jit_tier",
            [](const PyProgram& p) {
                return std::string(p.exec.jit_tier == JitTier::First       ? "first"
                                   : p.exec.jit_tier == JitTier::Optimised ? "optimised"
                                                                           : "tiered");
            },
            [](PyProgram& p, const std::string& name) {
                if (name == "tiered") p.exec.jit_tier = JitTier::Tiered;
                else if (name == "first") p.exec.jit_tier = JitTier::First;
                else if (name == "optimised") p.exec.jit_tier = JitTier::Optimised;
                else throw py::value_error("unknown JIT tier '" + name + "': use tiered, first or optimised");
            },
            "The JIT's code: \"tiered\" (the default: quick code first; a stage that keeps drawing is compiled "
            "again with every optimization in the background), \"first\" or \"optimised\" (from the first "
            "draw); the same bits.")
        .def_property(
            "cache_dir", [](const PyProgram& p) { return p.exec.code_cache_dir; },
            [](PyProgram& p, const std::string& dir) { p.exec.code_cache_dir = dir; },
            "The JIT's code cache directory: compiled code kept there is loaded by later programs and runs "
            "instead of compiling (\"\": $GLSLRUN_CACHE_DIR, else $XDG_CACHE_HOME/glslrun, else "
            "~/.cache/glslrun).")
        .def_property(
            "cache", [](const PyProgram& p) { return p.exec.code_cache; },
            [](PyProgram& p, bool on) { p.exec.code_cache = on; },
            "Whether the JIT uses its code cache (False, or GLSLRUN_NO_CACHE=1: never read nor written).")
        .def_property_readonly(
            "jit_compiles",
            [](const PyProgram& p) {
                const Program::JitCompiles c = p.jit_compiles();
                py::dict d;
                d["compiled"] = c.compiled;
                d["loaded"] = c.loaded;
                d["optimised"] = c.optimised;
                return d;
            },
            "The shaders the JIT compiled so far ('compiled') and loaded from the code cache ('loaded'); of "
            "those, its second tier's ('optimised': a stage that kept drawing, compiled again with every "
            "optimization in the background).")
        .def_property(
            "max_loop_iterations", [](const PyProgram& p) { return p.exec.max_loop_iterations; },
            [](PyProgram& p, uint64_t n) { p.exec.max_loop_iterations = n; },
            "The iterations one loop may run before the run stops with an error.")
        .def_property(
            "max_draw_instructions", [](const PyProgram& p) { return p.exec.max_draw_instructions; },
            [](PyProgram& p, uint64_t n) { p.exec.max_draw_instructions = n; },
            "The shader instructions one draw or run_* call may execute, all its batches together, before it "
            "stops with glslrun.Error (default 2^32).")
        .def_property(
            "max_render_instructions", [](const PyProgram& p) { return p.exec.max_render_instructions; },
            [](PyProgram& p, uint64_t n) { p.exec.max_render_instructions = n; },
            "The shader instructions one render() may execute, all its passes and draws together, before it "
            "stops with glslrun.Error (default 2^36, about 7 minutes of one core).")
        .def("dump_ir", &Program::dump_ir, "The intermediate representation of both stages, as glslrun --dump-ir prints it.")
        .def(
            "run_vertices",
            [](PyProgram& p, const py::dict& inputs, uint32_t count, const scene::Scene* scene, size_t object) {
                return run_batch(p, inputs, count, scene, object, true);
            },
            py::arg("inputs"), py::arg("count") = 0, py::arg("scene") = nullptr, py::arg("object") = 0,
            "Runs the vertex shader on arrays {attribute: (count, components)}; returns {output: array}. "
            "With a scene, in the state its object number `object` is drawn with; else in GL's defaults.")
        .def(
            "run_fragments",
            [](PyProgram& p, const py::dict& inputs, uint32_t count, const scene::Scene* scene, size_t object) {
                return run_batch(p, inputs, count, scene, object, false);
            },
            py::arg("inputs"), py::arg("count") = 0, py::arg("scene") = nullptr, py::arg("object") = 0,
            "Runs the fragment shader on arrays {input: (count, components)} in 2x2 quads; returns {output: "
            "array}, with 'discarded'. `scene` and `object` as for run_vertices.");
}

}  // namespace

void register_error(py::module_& m) {
    static py::exception<ErrorException> error_type(m, "Error", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const ErrorException& e) {
            py::list diagnostics;
            for (const Diagnostic& d : e.error.diagnostics)
                diagnostics.append(py::make_tuple(d.file, d.line, d.message, d.warning));
            std::string text = e.error.str();
            while (!text.empty() && text.back() == '\n') text.pop_back();
            py::object instance = py::handle(error_type.ptr())(text);
            instance.attr("diagnostics") = diagnostics;
            PyErr_SetObject(error_type.ptr(), instance.ptr());
        }
    });
}

}  // namespace glslrun::python

PYBIND11_MODULE(glslrun, m) {
    using namespace glslrun::python;
    m.doc() =
        "glslrun: legacy GLSL (1.10/1.20) on the CPU.\n\n"
        "render(vert, frag, scene) renders a scene file to an H x W x 4 uint8 array; Program compiles "
        "shaders, sets uniforms, renders Scenes and runs vertex or fragment batches on numpy arrays. "
        "Errors raise glslrun.Error with file:line diagnostics. See docs/library.md.";
    m.attr("__version__") = GLSLRUN_VERSION_STRING;
    register_error(m);
    bind_program(m);
    bind_scene(m);
    bind_mesh(m);
    bind_state(m);
    // Python's atexit runs before the C exit handlers: a background compile
    // stops there (glslrun::stop_background_compiles).
    py::module_::import("atexit").attr("register")(py::cpp_function([] { glslrun::stop_background_compiles(); }));
}
