// Finding and loading the JIT plugin (runtime/jit_plugin.h says why it is one).
#include "runtime/jit_plugin.h"

#include <dlfcn.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

#include "runtime/compile_queue.h"

namespace glslrun::rt {

namespace {

namespace fs = std::filesystem;

#ifdef GLSLRUN_HAVE_JIT
constexpr const char* kPluginName = "libglslrun-jit.so";

bool is_file(const fs::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// The directory of the binary this code was linked into.
fs::path own_directory() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&jit_plugin_present), &info) == 0 || !info.dli_fname) return {};
    std::error_code ec;
    fs::path binary = fs::canonical(info.dli_fname, ec);
    return ec ? fs::path() : binary.parent_path();
}

std::vector<fs::path> candidates() {
    if (const char* env = std::getenv("GLSLRUN_JIT_PLUGIN"); env && *env) return {fs::path(env)};
    std::vector<fs::path> paths;
    if (fs::path d = own_directory(); !d.empty()) {
        paths.push_back(d / kPluginName);
        paths.push_back(d / "glslrun" / kPluginName);
        paths.push_back(d / GLSLRUN_JIT_FROM_BIN / kPluginName);
    }
    paths.push_back(fs::path(GLSLRUN_JIT_INSTALL_DIR) / kPluginName);
    paths.push_back(fs::path(GLSLRUN_JIT_BUILD_DIR) / kPluginName);
    return paths;
}

// The first candidate that exists; empty where none does.
const fs::path& plugin_path() {
    static const fs::path found = [] {
        for (const fs::path& p : candidates())
            if (is_file(p)) return p;
        return fs::path();
    }();
    return found;
}

struct Loaded {
    const JitEntryPoints* entry = nullptr;
    std::string error;
};

Loaded load_one(const fs::path& path) {
    // RTLD_LOCAL: LLVM's symbols stay the plugin's own.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) return {nullptr, std::string("the JIT plugin could not be loaded: ") + dlerror()};
    // LLVM's static destructors were registered by this dlopen: a background compile must stop first.
    stop_compiles_before_exit();
    using Entry = const JitEntryPoints* (*)(const char*);
    auto entry = reinterpret_cast<Entry>(dlsym(handle, "glslrun_jit_entry_points"));
    if (!entry) return {nullptr, path.string() + " is not glslrun's JIT plugin"};
    const JitEntryPoints* points = entry(GLSLRUN_JIT_BUILD_KEY);
    if (!points) return {nullptr, "the JIT plugin " + path.string() + " belongs to another build of glslrun"};
    return {points, {}};
}

// The first candidate that loads and is this build's: an install elsewhere
// on the machine (another build's plugin) does not hide the build tree's.
Loaded load() {
    Loaded first;
    for (const fs::path& path : candidates()) {
        if (!is_file(path)) continue;
        Loaded l = load_one(path);
        if (l.entry) return l;
        if (first.error.empty()) first = l;
    }
    if (first.error.empty()) first.error = std::string("the JIT plugin (") + kPluginName + ") was not found";
    return first;
}

// Set once the plugin has loaded: the one fact about it that changes.
std::atomic<bool>& loaded_flag() {
    static std::atomic<bool> flag{false};
    return flag;
}

const Loaded& loaded() {
    static const Loaded once = [] {  // thread-safe; the plugin stays for the process
        Loaded l = load();
        loaded_flag().store(l.entry != nullptr);
        return l;
    }();
    return once;
}
#endif

}  // namespace

const JitEntryPoints* jit_plugin() {
#ifdef GLSLRUN_HAVE_JIT
    return loaded().entry;
#else
    return nullptr;
#endif
}

std::string jit_plugin_error() {
#ifdef GLSLRUN_HAVE_JIT
    return loaded().error;
#else
    return "this glslrun was built without the JIT";
#endif
}

bool jit_plugin_loaded() {
#ifdef GLSLRUN_HAVE_JIT
    return loaded_flag().load();
#else
    return false;
#endif
}

bool jit_plugin_present() {
#ifdef GLSLRUN_HAVE_JIT
    return !plugin_path().empty();
#else
    return false;
#endif
}

}  // namespace glslrun::rt
