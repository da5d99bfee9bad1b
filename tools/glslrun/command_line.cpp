#include "command_line.h"

#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "runtime/jit_plugin.h"
#include "scene/scene_reader.h"

namespace glslrun::cli {

void add_precision_option(CLI::App& app, Precision& precision) {
    app.add_option_function<std::string>(
           "--precision",
           [&precision](const std::string& name) { precision = parse_precision(name).value(); },
           "reference (double, slow), precise (fp32, the default) or fast (fp32, GPU-style approximations)")
        ->check([](const std::string& name) {
            auto parsed = parse_precision(name);
            return parsed ? std::string() : parsed.error().diagnostics.front().message;
        });
}

void add_backend_option(CLI::App& app, Backend& backend) {
    app.add_option_function<std::string>(
           "--backend", [&backend](const std::string& name) { backend = parse_backend(name).value(); },
           "who runs the shaders: interp (the interpreter), jit (native code compiled by LLVM, the "
           "interpreter's bits) or auto (the default: jit where built in). Reference precision always "
           "runs on the interpreter")
        ->check([](const std::string& name) {
            auto parsed = parse_backend(name);
            if (!parsed) return parsed.error().diagnostics.front().message;
            if (*parsed == Backend::Jit && !jit_available()) return rt::jit_plugin_error();
            return std::string();
        });
}

void add_code_cache_options(CLI::App& app) {
    app.add_option_function<std::string>(
           "--cache-dir", [](const std::string& dir) { ::setenv("GLSLRUN_CACHE_DIR", dir.c_str(), 1); },
           "the JIT's code cache: compiled code is kept there and loaded by later runs instead of compiling "
           "(default: $GLSLRUN_CACHE_DIR, else $XDG_CACHE_HOME/glslrun, else ~/.cache/glslrun)")
        ->type_name("DIR")
        ->check([](const std::string& dir) { return dir.empty() ? std::string("the path is empty") : std::string(); });
    app.add_flag_callback(
        "--no-cache", [] { ::setenv("GLSLRUN_NO_CACHE", "1", 1); },
        "neither read nor write the JIT's code cache (as GLSLRUN_NO_CACHE=1)");
}

void warn_about_code_cache(Backend backend) {
    if (backend == Backend::Interp) return;
    const CodeCacheStatus status = code_cache_status(ExecOptions{});
    if (!status.warning.empty()) std::fprintf(stderr, "glslrun: warning: %s\n", status.warning.c_str());
}

void add_define_option(CLI::App& app, std::vector<std::string>& defines) {
    app.add_option("-D,--define", defines,
                   "NAME[=VALUE]: #define NAME VALUE before every shader source, as glslangValidator's -D (line "
                   "numbers unchanged); repeatable")
        ->type_name("NAME[=VALUE]")
        ->allow_extra_args(false)
        ->check([](const std::string& d) {
            std::string name = d.substr(0, d.find('='));
            bool ident = !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
            for (char c : name) ident = ident && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
            if (!ident) return "-D '" + d + "': NAME must be an identifier (letters, digits, _)";
            if (name.starts_with("GL_") || name.find("__") != std::string::npos)
                return "-D '" + d + "': names with GL_ or __ are reserved by GLSL";
            if (d.find_first_of(std::string("\n\r\0", 3)) != std::string::npos)
                return "-D '" + d + "': the value must be on one line";
            return std::string();
        });
}

void add_include_option(CLI::App& app, std::vector<std::string>& dirs) {
    app.add_option("-I,--include-dir", dirs,
                   "DIR: where `#include \"name\"` looks after the including file's own directory (with "
                   "`#extension GL_GOOGLE_include_directive : require` in the shader, as glslangValidator's -I); "
                   "repeatable, searched in order")
        ->type_name("DIR")
        ->allow_extra_args(false)
        ->check(CLI::ExistingDirectory);
}

std::optional<std::pair<int, int>> parse_int_pair(std::string_view text, std::string_view separators) {
    int a = 0, b = 0;
    const char* end = text.data() + text.size();
    auto [after_a, ea] = std::from_chars(text.data(), end, a);
    if (ea != std::errc() || after_a == end || separators.find(*after_a) == std::string_view::npos) return std::nullopt;
    auto [after_b, eb] = std::from_chars(after_a + 1, end, b);
    if (eb != std::errc() || after_b != end) return std::nullopt;
    return std::pair{a, b};
}

namespace {

// CLI11 says only "The following argument was not expected: --treads": name
// the option the user probably meant. "" when no argument looks like one.
std::string misspelt_option(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* o : app.get_options())
        for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
    std::vector<std::string_view> views(names.begin(), names.end());
    for (const std::string& arg : app.remaining()) {
        if (!arg.starts_with("--")) continue;
        std::string written = arg.substr(0, arg.find('='));
        std::string best = scene::detail::closest(written, views);
        return fmt::format("{}: error: unknown option '{}'{} ({} --help lists the options)", app.get_name(), written,
                           best.empty() ? "" : fmt::format("; did you mean '{}'?", best), app.get_name());
    }
    return {};
}

}  // namespace

int parse_command_line(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ExtrasError& e) {
        if (std::string message = misspelt_option(app); !message.empty()) {
            std::fprintf(stderr, "%s\n", message.c_str());
            return kToolError;
        }
        return app.exit(e) == 0 ? 0 : kToolError;
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : kToolError;
    }
    return -1;
}

}  // namespace glslrun::cli
