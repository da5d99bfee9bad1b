// The scene half of `import glslrun`: scene files, rendering to numpy arrays
// (H x W x 4 uint8, top row first, the bytes of the command line's PNG),
// images and their comparison, and the error report as a dict.
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>

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

ExecOptions exec_options(unsigned threads, const std::string& precision) {
    ExecOptions o;
    o.threads = threads;
    o.precision = take(parse_precision(precision));
    return o;
}

py::array_t<uint8_t> render_program(Program& program, const scene::Scene& scene, double time_limit) {
    scene::Image image;
    run_interruptibly(program.exec, time_limit, [&] { image = take(scene::render_image(program, scene)); });
    return to_array(image);
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

py::dict error_report(const std::string& vertex, const std::string& fragment, const std::string& scene_path,
                      const std::string& mode, unsigned threads) {
    scene::ErrorReportOptions options;
    options.mode = take(parse_precision(mode));
    options.threads = threads;
    auto scene = take(scene::load_scene(scene_path));
    auto vertex_sources = take(scene::read_shader_files({vertex}));
    auto fragment_sources = take(scene::read_shader_files({fragment}));
    scene::ErrorReport report;
    {
        py::gil_scoped_release release;
        report = take(scene::measure_error(vertex_sources, fragment_sources, scene, options));
    }
    py::dict out = keys_to_dict(scene::format_error_keys(report));
    out["notes"] = report.notes;
    out["reference_image"] = to_array(report.reference_image);
    out["mode_image"] = to_array(report.mode_image);
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
            "load", [](const std::string& path) { return take(scene::load_scene(path)); }, py::arg("path"))
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
            py::arg("height"));
    py::class_<Program> program = py::reinterpret_borrow<py::class_<Program>>(m.attr("Program"));
    program.def("render", &render_program, py::arg("scene"), py::arg("time_limit") = 0.0,
                "Renders the scene: an H x W x 4 uint8 array, top row first (as the PNG). A render still running "
                "after time_limit seconds (> 0) raises glslrun.Error; Ctrl-C stops it (KeyboardInterrupt).");

    m.def(
        "render",
        [](const std::string& vertex, const std::string& fragment, const std::string& scene_path, unsigned threads,
           const std::string& precision, double time_limit) {
            scene::Image image;
            ExecOptions exec = exec_options(threads, precision);
            run_interruptibly(exec, time_limit,
                              [&] { image = take(scene::render_files(vertex, fragment, scene_path, exec)); });
            return to_array(image);
        },
        py::arg("vertex"), py::arg("fragment"), py::arg("scene"), py::arg("threads") = 0,
        py::arg("precision") = "precise", py::arg("time_limit") = 0.0,
        "glslrun a.vert a.frag scene.toml in memory: an H x W x 4 uint8 array, equal to the command line's PNG. "
        "time_limit and Ctrl-C as for Program.render.");
    m.def(
        "read_png", [](const std::string& path) { return to_array(take(scene::read_png(path))); }, py::arg("path"));
    m.def(
        "write_png",
        [](const py::object& image, const std::string& path) { check(scene::write_png(to_image(image), path)); },
        py::arg("image"), py::arg("path"));
    m.def("compare_images", &compare, py::arg("reference"), py::arg("actual"), py::arg("tolerance") = 1,
          "Per-channel differences of two H x W x 4 uint8 images (as glslrun --compare).");
    m.def("error_report", &error_report, py::arg("vertex"), py::arg("fragment"), py::arg("scene"),
          py::arg("mode") = "fast", py::arg("threads") = 0,
          "The scene in `mode` against Reference (glslrun --error-report): the report's keys as a dict, with "
          "'notes', 'reference_image' and 'mode_image'.");
}

}  // namespace glslrun::python
