// The compiled shaders of one Program, by specialization key: made at the
// first draw that needs them and shared by every worker and later draw.
//
// Tiering: a draw that asks for the JIT without waiting for it (Backend::Auto)
// gets the interpreter while LLVM compiles on a background thread, and the
// JIT's code from the first draw after it is ready; Backend::Jit waits. The
// images are the same either way (the backends compute the same bits).
#pragma once
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <tuple>
#include <vector>

#include "runtime/backend.h"

namespace glslrun::rt {

class BackendCache {
public:
    struct Key {
        ir::Stage stage;
        Backend backend;  // Interp or Jit
        Precision precision;
        uint32_t fast_ops;
        bool avx2;  // the vector ISA the code was made for
        bool quick_codegen;  // ExecOptions::jit_quick_codegen
        auto tie() const { return std::tie(stage, backend, precision, fast_ops, avx2, quick_codegen); }
        bool operator<(const Key& o) const { return tie() < o.tie(); }
    };
    BackendCache() = default;
    BackendCache(const BackendCache&) = delete;
    BackendCache& operator=(const BackendCache&) = delete;
    ~BackendCache();  // waits for the background compiles

    // The code for `key`; for a JIT key with `wait` false, the interpreter's
    // until the JIT's is ready (compiled in the background meanwhile).
    const CompiledShader& get(const ir::Shader& shader, const Key& key, bool wait);
    // Seconds LLVM spent compiling this program's shaders so far.
    double jit_compile_seconds() const;

private:
    const CompiledShader& compile_now(const ir::Shader& shader, const Key& key);

    mutable std::mutex mutex_;
    std::condition_variable compiled_;
    std::map<Key, std::unique_ptr<CompiledShader>> shaders_;
    std::map<Key, bool> compiling_;  // keys whose background compile has started
    std::vector<std::thread> threads_;
    double jit_compile_seconds_ = 0;
};

}  // namespace glslrun::rt
