// The scene half of `import glslrun`: scene files, rendering to numpy arrays
// (H x W x 4 uint8, top row first, the bytes of the command line's PNG),
// images and their comparison, and the error report as a dict.
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <sstream>
#include <string_view>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "module.h"

namespace glslrun::python {

py::array_t<uint8_t> to_array(const scene::Image& image) {
    py::array_t<uint8_t> a({size_t(image.height), size_t(image.width), size_t(4)});
    std::copy(image.rgba.begin(), image.rgba.end(), a.mutable_data());
    return a;
}

scene::Image to_image(const py::object& object) {
    // uint8 only: a cast would wrap 300 to 44 and make NaN anything. Sides are
    // checked before they narrow to int (3000000000 rows became -1294967296).
    // The shape is checked on the array as given, before a contiguous copy
    // (a broadcast view of 2^40 pixels costs nothing until it is copied).
    constexpr const char* kShape = "an image is an H x W x 4 uint8 array, each side at most 16384 (and at least 1)";
    if (!py::isinstance<py::array_t<uint8_t>>(object)) throw py::type_error(kShape);
    auto given = py::reinterpret_borrow<py::array>(object);
    auto side_ok = [](py::ssize_t side) { return side >= 1 && side <= kMaxFramebufferSide; };
    if (given.ndim() != 3 || given.shape(2) != 4 || !side_ok(given.shape(0)) || !side_ok(given.shape(1)))
        throw py::value_error(kShape);
    auto a = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>::ensure(object);
    if (!a) throw py::error_already_set();  // the copy failed: MemoryError
    return {int(a.shape(1)), int(a.shape(0)), std::vector<uint8_t>(a.data(), a.data() + a.size())};
}

py::array_t<double> uniform_numbers(const std::string& name, const py::object& value) {
    // Kinds b, i, u, f: bool, int, unsigned, float. None would become NaN
    // through a float cast, a string an error deep in numpy.
    py::array a = py::array::ensure(value);
    char kind = a ? a.dtype().kind() : 'O';
    if (!a || (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f'))
        throw py::type_error("uniform '" + name + "' takes numbers (a number, a sequence or an array of them), not " +
                             std::string(py::str(py::type::of(value).attr("__name__"))));
    return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

std::vector<scene::UniformSetting> uniform_settings(const py::object& uniforms, const std::string& what) {
    std::vector<scene::UniformSetting> settings;
    if (uniforms.is_none()) return settings;
    if (!py::isinstance<py::dict>(uniforms)) throw py::type_error(what + " takes a dict {name: value}");
    for (auto [key, value] : py::reinterpret_borrow<py::dict>(uniforms)) {
        std::string name = py::cast<std::string>(key);
        py::array_t<double> numbers = uniform_numbers(name, py::reinterpret_borrow<py::object>(value));
        scene::UniformSetting s{name, std::vector<double>(numbers.data(), numbers.data() + numbers.size()), true,
                                {what, 0}};
        for (double d : s.values) s.integral = s.integral && d == std::trunc(d);
        settings.push_back(std::move(s));
    }
    return settings;
}

void run_interruptibly(ExecOptions& exec, double time_limit, const std::function<void()>& work) {
    std::atomic<bool> cancel{false};
    const std::atomic<bool>* given = exec.cancel;
    const auto deadline = exec.deadline;
    exec.cancel = &cancel;
    if (time_limit > 0) exec.set_time_limit(time_limit);
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false, interrupted = false;
    std::exception_ptr error;
    {
        py::gil_scoped_release release;
        std::thread worker([&] {
            try {
                work();
            } catch (...) {
                error = std::current_exception();
            }
            std::lock_guard lock(mutex);
            done = true;
            finished.notify_one();
        });
        std::unique_lock lock(mutex);
        while (!finished.wait_for(lock, std::chrono::milliseconds(20), [&] { return done; })) {
            if (interrupted) continue;
            lock.unlock();
            {
                py::gil_scoped_acquire acquire;
                // Only the main thread sees signals; elsewhere this returns 0.
                interrupted = PyErr_CheckSignals() != 0;
            }
            if (interrupted) cancel = true;
            lock.lock();
        }
        lock.unlock();
        worker.join();
    }
    exec.cancel = given;
    exec.deadline = deadline;
    if (interrupted) throw py::error_already_set();  // the KeyboardInterrupt that PyErr_CheckSignals raised
    if (error) std::rethrow_exception(error);
}

namespace {

// An unwritable code cache directory is a warning (compiled code is not kept), never an error.
void warn_about_code_cache(const ExecOptions& exec) {
    if (exec.backend == Backend::Interp) return;
    const CodeCacheStatus status = code_cache_status(exec);
    if (!status.warning.empty() && PyErr_WarnEx(PyExc_RuntimeWarning, status.warning.c_str(), 1) < 0)
        throw py::error_already_set();  // warnings made errors
}

ExecOptions exec_options(unsigned threads, const std::string& precision, const std::string& backend) {
    ExecOptions o;
    o.threads = threads;
    o.precision = take(parse_precision(precision));
    o.backend = take(parse_backend(backend));
    return o;
}

// The variable a uniform name sets: "arr" for "arr[2]", "s" for "s.f".
std::string_view variable_of(std::string_view name) { return name.substr(0, name.find_first_of("[.")); }

// render_image, but the [uniforms] entries that no program uses, which the
// render skips as GL does, are raised as RuntimeWarning afterwards (the
// command line prints them), with the GIL held.
scene::Image render_warning(Program& program, const scene::Scene& scene, double time_limit) {
    std::vector<Diagnostic> warnings;
    scene::Image image;
    run_interruptibly(program.exec, time_limit, [&] {
        scene::ScenePrograms programs = take(scene::ScenePrograms::compile(program, scene));
        warnings = programs.warnings();
        Framebuffer fb = take(Framebuffer::create(scene.width, scene.height, false, scene::color_buffers(scene)));
        take(scene::render_scene(programs, scene, fb));
        image = scene::read_framebuffer(fb);
    });
    for (const Diagnostic& w : warnings)
        if (PyErr_WarnEx(PyExc_RuntimeWarning, w.str().c_str(), 1) < 0) throw py::error_already_set();
    return image;
}

// Whether the scene sets anything of what `settings` set: only then must the
// settings be applied again after the scene's (a copy per render; a scene
// with passes always, since its passes' own programs need them too).
bool scene_sets_any(const scene::Scene& scene, const std::vector<scene::UniformSetting>& settings) {
    if (!scene.passes.empty()) return true;
    auto hits = [&](const std::vector<scene::UniformSetting>& list) {
        for (const scene::UniformSetting& a : list)
            for (const scene::UniformSetting& b : settings)
                if (variable_of(a.name) == variable_of(b.name)) return true;
        return false;
    };
    if (hits(scene.uniforms)) return true;
    for (const scene::Object& o : scene.objects)
        if (hits(o.uniforms)) return true;
    return false;
}

// The uniforms the user set (set_uniform, then `uniforms`) win over the
// scene's and its objects' [uniforms], on a copy of the scene. set_uniform's
// values are in the program already: without a clash, no copy is needed.
py::array_t<uint8_t> render_program(PyProgram& program, const scene::Scene& scene, const py::object& uniforms,
                                    double time_limit) {
    std::vector<scene::UniformSetting> settings = uniform_settings(uniforms, "uniforms");
    // A previous render's `uniforms` or scene may have changed them since.
    check(scene::apply_uniforms(program, program.user_uniforms));
    if (!settings.empty() || scene_sets_any(scene, program.user_uniforms))
        settings.insert(settings.begin(), program.user_uniforms.begin(), program.user_uniforms.end());
    std::optional<scene::Scene> overridden;
    if (!settings.empty()) {
        overridden = scene;
        scene::override_uniforms(*overridden, settings);
    }
    return to_array(render_warning(program, overridden ? *overridden : scene, time_limit));
}

// "key value" lines (scene::format_error_keys) as a dict; numbers as numbers.
py::dict keys_to_dict(const std::string& lines) {
    py::dict out;
    std::istringstream in(lines);
    std::string line;
    while (std::getline(in, line)) {
        size_t space = line.find(' ');
        if (space == std::string::npos) continue;
        size_t start = line.find_first_not_of(' ', space);
        std::string key = line.substr(0, space), value = start == std::string::npos ? "" : line.substr(start);
        char* end = nullptr;
        double number = std::strtod(value.c_str(), &end);
        bool numeric = !value.empty() && end == value.c_str() + value.size();
        if (numeric)
            out[py::str(key)] = number;
        else
            out[py::str(key)] = value;
    }
    return out;
}

// The files of render(), error_report() and check_undefined(), as the
// command line takes them: with `scene`, the shaders by position, None for
// a stage GL's fixed function draws; without it, the files given sorted by
// their names (a.frag, scene.toml), so that render("scene.toml") and
// render("a.frag", "scene.toml") read as `glslrun scene.toml` does.
struct FileArgs {
    std::vector<std::string> vertex, fragment;  // empty: GL's fixed function
    std::string scene;
};

FileArgs file_args(const py::object& vertex, const py::object& fragment, const py::object& scene,
                   const char* function) {
    auto text = [](const py::object& o) { return o.is_none() ? std::vector<std::string>{} : paths(o); };
    FileArgs out;
    if (!scene.is_none()) {
        out = {text(vertex), text(fragment), py::cast<std::string>(scene)};
        return out;
    }
    for (const py::object* o : {&vertex, &fragment})
        for (const std::string& file : text(*o)) {
            const std::string stage = scene::shader_stage_of(file);
            if (file.ends_with(".toml") && out.scene.empty())
                out.scene = file;
            else if (!stage.empty())
                (stage == "vert" ? out.vertex : out.fragment).push_back(file);
            else
                throw py::value_error(fmt::format(
                    "{}(): cannot tell what '{}' is from its name: pass {}(vertex, fragment, scene), None for a "
                    "stage that GL's fixed function draws",
                    function, file, function));
        }
    if (out.scene.empty())
        throw py::value_error(fmt::format(
            "{}() needs a scene file (.toml): {}(\"a.vert\", \"a.frag\", \"scene.toml\"); a shader left out "
            "(None) is drawn with GL's fixed function, generated from the scene",
            function, function));
    return out;
}

// A scene and its shaders, as the module-level functions that take paths read them.
struct SceneInputs {
    scene::Scene scene;
    std::vector<ShaderSource> vertex, fragment;
};

SceneInputs read_inputs(const FileArgs& files, const char* function) {
    if (files.vertex.empty() && files.fragment.empty())
        throw py::value_error(fmt::format("{}() looks at your shaders: give a vertex or a fragment shader (a scene "
                                          "without shaders is GL's fixed function alone: render(\"scene.toml\"))",
                                          function));
    return {take(scene::load_scene(files.scene)), take(scene::read_shader_files(files.vertex)),
            take(scene::read_shader_files(files.fragment))};
}

py::dict error_report(const py::object& vertex, const py::object& fragment, const py::object& scene_path,
                      const std::string& mode, unsigned threads, const std::vector<std::string>& include_dirs) {
    scene::ErrorReportOptions options;
    options.mode = take(parse_precision(mode));
    options.threads = threads;
    options.compile.include_dirs = include_dirs;
    SceneInputs in = read_inputs(file_args(vertex, fragment, scene_path, "error_report"), "error_report");
    scene::ErrorReport report;
    {
        py::gil_scoped_release release;
        report = take(scene::measure_error(in.vertex, in.fragment, in.scene, options));
    }
    py::dict out = keys_to_dict(scene::format_error_keys(report));
    out["notes"] = report.notes;
    out["reference_image"] = to_array(report.reference_image);
    out["mode_image"] = to_array(report.mode_image);
    return out;
}

// check_undefined() (glslrun/scene/undefined.h): one dict per finding.
py::list check_undefined(const py::object& vertex, const py::object& fragment, const py::object& scene_path,
                         const std::string& precision, const std::string& backend,
                         const std::vector<std::string>& include_dirs) {
    ExecOptions exec = exec_options(1, precision, backend);
    CompileOptions compile;
    compile.include_dirs = include_dirs;
    SceneInputs in = read_inputs(file_args(vertex, fragment, scene_path, "check_undefined"), "check_undefined");
    scene::UndefinedReport report;
    {
        py::gil_scoped_release release;
        report = take(scene::check_undefined(in.vertex, in.fragment, in.scene, exec, compile));
    }
    py::list out;
    for (const scene::UndefinedFinding& f : report.findings) {
        const scene::UndefinedInvocation& i = f.first;
        py::dict first(py::arg("stage") = i.vertex ? "vertex" : "fragment", py::arg("draw") = i.draw,
                       py::arg("pass") = i.pass, py::arg("program") = i.program, py::arg("operands") = i.operands);
        if (i.vertex) first["vertex"] = i.vertex_index;
        else first["pixel"] = py::make_tuple(i.x, i.y);
        out.append(py::dict(py::arg("op") = f.op, py::arg("condition") = f.condition,
                            py::arg("stage") = f.vertex ? "vertex" : "fragment", py::arg("file") = f.file,
                            py::arg("line") = f.line, py::arg("column") = f.column, py::arg("text") = f.line_text,
                            py::arg("count") = f.count, py::arg("first") = first,
                            py::arg("reference") = f.mode_values[0], py::arg("precise") = f.mode_values[1],
                            py::arg("fast") = f.mode_values[2], py::arg("value_note") = f.value_note,
                            py::arg("gpu") = f.gpu));
    }
    return out;
}

py::dict compare(const py::object& reference, const py::object& actual, int tolerance) {
    scene::CompareOptions options;
    options.tolerance = tolerance;
    options.min_fraction_within = 1.0;
    auto stats = take(scene::compare_images(to_image(reference), to_image(actual), options));
    return py::dict(py::arg("passed") = stats.passed, py::arg("max_diff") = stats.max_diff,
                    py::arg("mean_diff") = stats.mean_diff, py::arg("differing") = stats.differing,
                    py::arg("pixels") = stats.pixels, py::arg("worst") = py::make_tuple(stats.worst_x, stats.worst_y),
                    py::arg("summary") = stats.summary());
}

}  // namespace

void bind_scene(py::module_& m) {
    py::class_<scene::Scene>(m, "Scene", "A scene file's legacy GL state (docs/scene-format.md).")
        .def_static(
            "load", [](const std::string& path) { return take(scene::load_scene(path)); }, py::arg("path"),
            "A scene file (TOML, docs/scene-format.md); errors cite its file:line.")
        .def_static(
            "parse",
            [](const std::string& toml, const std::string& path) { return take(scene::parse_scene(toml, path)); },
            py::arg("toml"), py::arg("path") = "<string>",
            "A scene from TOML text; relative mesh and texture paths are relative to `path`'s directory.")
        .def_readonly("path", &scene::Scene::path)
        .def_readonly("width", &scene::Scene::width)
        .def_readonly("height", &scene::Scene::height)
        .def_property_readonly("objects", [](const scene::Scene& s) { return s.objects.size(); })
        .def_property_readonly("warnings",
                               [](const scene::Scene& s) {
                                   std::vector<std::string> out;
                                   for (const Diagnostic& d : s.warnings) out.push_back(d.str());
                                   return out;
                               })
        .def(
            "resize", [](scene::Scene& s, int w, int h) { check(scene::resize_scene(s, w, h)); }, py::arg("width"),
            py::arg("height"),
            "Changes the output size; a perspective camera without an explicit aspect keeps width/height.");
    py::class_<PyProgram> program = py::reinterpret_borrow<py::class_<PyProgram>>(m.attr("Program"));
    program.def("render", &render_program, py::arg("scene"), py::kw_only(), py::arg("uniforms") = py::none(),
                py::arg("time_limit") = 0.0,
                "Renders the scene: an H x W x 4 uint8 array, top row first (as the PNG).\n\n"
                "Uniforms set with set_uniform(), then those in `uniforms` ({name: value}), override the "
                "scene's and its objects' [uniforms], as the command line's --uniform does. Like the scene's, "
                "`uniforms` stay set in the program afterwards (uniforms are program state, as in GL), but "
                "set_uniform()'s values are set again on every render. A render still running after time_limit "
                "seconds (> 0) raises glslrun.Error; Ctrl-C stops it (KeyboardInterrupt).");

    m.def(
        "render",
        [](const py::object& vertex, const py::object& fragment, const py::object& scene_path, unsigned threads,
           const std::string& precision, const py::object& uniforms, const std::string& backend,
           double time_limit, const std::string& cache_dir, bool cache, const std::vector<std::string>& include_dirs) {
            ExecOptions exec = exec_options(threads, precision, backend);
            exec.code_cache_dir = cache_dir;
            exec.code_cache = cache;
            warn_about_code_cache(exec);
            const FileArgs files = file_args(vertex, fragment, scene_path, "render");
            scene::Scene scene = take(scene::load_scene(files.scene));
            scene::override_uniforms(scene, uniform_settings(uniforms, "uniforms"));
            CompileOptions compile;
            compile.include_dirs = include_dirs;
            // No shaders: every draw in GL's fixed function, as `glslrun scene.toml` draws it.
            const bool fixed = files.vertex.empty() && files.fragment.empty();
            if (fixed) {
                const std::string w = scene::fixed_function_warning(scene);
                if (!w.empty() && PyErr_WarnEx(PyExc_RuntimeWarning, w.c_str(), 1) < 0) throw py::error_already_set();
                scene::use_fixed_function(scene);
            }
            Program program = take(fixed ? scene::unused_main_program()
                                         : scene::compile_files(files.vertex, files.fragment, compile));
            program.exec = exec;
            return to_array(render_warning(program, scene, time_limit));
        },
        py::arg("vertex") = py::none(), py::arg("fragment") = py::none(), py::arg("scene") = py::none(), py::arg("threads") = 0,
        py::arg("precision") = "precise", py::kw_only(), py::arg("uniforms") = py::none(), py::arg("backend") = "auto",
        py::arg("time_limit") = 0.0, py::arg("cache_dir") = "", py::arg("cache") = true,
        py::arg("include_dirs") = std::vector<std::string>{},
        "glslrun a.vert a.frag scene.toml in memory: an H x W x 4 uint8 array, equal to the command line's PNG.\n\n"
        "A stage left out is GL's fixed function, generated from the scene's state, as on the command line: "
        "render(None, \"a.frag\", \"scene.toml\"), or the files by their names, render(\"a.frag\", "
        "\"scene.toml\") and render(\"scene.toml\") (no shader: every draw in fixed function). "
        "`uniforms` ({name: value}) overrides the scene's [uniforms], as the command line's --uniform does; "
        "`backend` is \"auto\", \"jit\" or \"interp\" (the same bits); time_limit and Ctrl-C as for "
        "Program.render. `cache_dir` and `cache`: the JIT's code cache, as Program.cache_dir and Program.cache "
        "(a directory that cannot be written is a RuntimeWarning). `include_dirs`: as the command line's -I.");
    m.def(
        "read_png", [](const std::string& path) { return to_array(take(scene::read_png(path))); }, py::arg("path"),
        "A PNG as an H x W x 4 uint8 array, top row first.");
    m.def(
        "write_png",
        [](const py::object& image, const std::string& path) { check(scene::write_png(to_image(image), path)); },
        py::arg("image"), py::arg("path"), "Writes an H x W x 4 uint8 array as an RGBA8 PNG (lossless).");
    m.def("compare_images", &compare, py::arg("reference"), py::arg("actual"), py::arg("tolerance") = 1,
          "Per-channel differences of two H x W x 4 uint8 images (as glslrun --compare).");
    m.def("error_report", &error_report, py::arg("vertex") = py::none(), py::arg("fragment") = py::none(),
          py::arg("scene") = py::none(),
          py::arg("mode") = "fast", py::arg("threads") = 0, py::kw_only(),
          py::arg("include_dirs") = std::vector<std::string>{},
          "The scene in `mode` against Reference (glslrun --error-report): the report's keys as a dict, with "
          "'notes', 'reference_image' and 'mode_image'. The files as render() takes them (one shader may be "
          "left out). `include_dirs`: as the command line's -I.");
    m.def("jit_available", &jit_available,
          "Whether the JIT can run here: LLVM's native code, in the plugin libglslrun-jit.so beside this "
          "module, loaded by this call or the first compile. Without it every backend runs the interpreter, "
          "which computes the same bits.");
    m.def("check_undefined", &check_undefined, py::arg("vertex") = py::none(), py::arg("fragment") = py::none(),
          py::arg("scene") = py::none(),
          py::arg("precision") = "precise", py::kw_only(), py::arg("backend") = "auto",
          py::arg("include_dirs") = std::vector<std::string>{},
          "The operations GLSL 1.10/1.20 leaves undefined that rendering the scene computes (glslrun "
          "--check-undefined, docs/debugging.md): one dict per source position and op, with 'op', 'condition', "
          "'stage', 'file', 'line', 'column', 'text' (the line), 'count' (invocations), 'first' (the first "
          "invocation: 'stage', 'draw', 'pass', 'program', 'operands' and 'pixel' or 'vertex'), what each "
          "precision mode returns for its operands ('reference', 'precise', 'fast', 'value_note') and what "
          "NVIDIA's GPU returned for such operands ('gpu', measured; '' where not measured). The files as render() "
          "takes them (one shader may be left out). `include_dirs`: as the command line's -I.");
}

}  // namespace glslrun::python
