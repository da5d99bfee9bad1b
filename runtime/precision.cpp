// The names of the precision modes and backends, as the command line spells them.
#include <fmt/format.h>

#include "glslrun/glslrun.h"

namespace glslrun {

const char* precision_name(Precision p) {
    switch (p) {
    case Precision::Reference: return "reference";
    case Precision::Precise: return "precise";
    case Precision::Fast: return "fast";
    }
    return "unknown";
}

Result<Precision> parse_precision(std::string_view name) {
    for (Precision p : {Precision::Reference, Precision::Precise, Precision::Fast})
        if (name == precision_name(p)) return p;
    return Error(fmt::format("unknown precision '{}': use reference, precise or fast", name));
}

const char* backend_name(Backend b) {
    switch (b) {
    case Backend::Interp: return "interp";
    case Backend::Jit: return "jit";
    case Backend::Auto: return "auto";
    }
    return "unknown";
}

Result<Backend> parse_backend(std::string_view name) {
    for (Backend b : {Backend::Interp, Backend::Jit, Backend::Auto})
        if (name == backend_name(b)) return b;
    return Error(fmt::format("unknown backend '{}': use interp, jit or auto", name));
}

}  // namespace glslrun
