// The Python module's shared pieces: errors as Python exceptions, numpy
// conversions. module.cpp binds programs and batches, module_scene.cpp
// scenes, images and the error report.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <functional>

#include "glslrun/scene.h"

namespace glslrun::python {

namespace py = pybind11;

// A glslrun Error on its way to Python: raised there as glslrun.Error, whose
// message is Error::str() ("file:line: error: ...", one per line) and whose
// `diagnostics` attribute lists (file, line, message, warning) tuples.
struct ErrorException {
    Error error;
};
void register_error(py::module_& m);

// The value of a Result, or ErrorException.
template <class T>
T take(Result<T> result) {
    if (!result) throw ErrorException{result.error()};
    return std::move(result.value());
}
inline void check(const Status& status) {
    if (!status) throw ErrorException{status.error()};
}

// A Program as Python holds it: the uniforms the user set with set_uniform,
// kept so that they win over a scene's [uniforms] on every render, as the
// command line's --uniform does.
struct PyProgram : Program {
    explicit PyProgram(Program&& p) : Program(std::move(p)) {}
    std::vector<scene::UniformSetting> user_uniforms;
};

// A path, or a list of paths, of a stage's shader files; None: none (GL's fixed function).
std::vector<std::string> paths(const py::object& p);

// {name: number, sequence or array} as uniform settings (a float uniform
// takes any number, an int one whole numbers); `what` names them in errors.
std::vector<scene::UniformSetting> uniform_settings(const py::object& uniforms, const std::string& what);
// The numbers of a uniform's value: TypeError for None, strings, objects.
py::array_t<double> uniform_numbers(const std::string& name, const py::object& value);
// Runs work() (a long render: C++ only, no Python objects) on another
// thread without the GIL, while this one waits and checks for signals every
// 20 ms: Ctrl-C (KeyboardInterrupt) sets `exec`'s cancel flag, so the work
// stops within a few ms and the exception is raised once it has. A
// `time_limit` > 0 sets exec's deadline (ExecOptions::set_time_limit) for
// the whole of the work.
void run_interruptibly(ExecOptions& exec, double time_limit, const std::function<void()>& work);

// An RGBA8 image as an H x W x 4 uint8 array, top row first, and back.
py::array_t<uint8_t> to_array(const scene::Image& image);
scene::Image to_image(const py::object& image);

void bind_scene(py::module_& m);
void bind_mesh(py::module_& m);   // after bind_scene
void bind_state(py::module_& m);  // after bind_scene

}  // namespace glslrun::python
