// The compiled shaders of one Program, by specialization key: made at the
// first draw that needs them and shared by every worker and later draw.
#pragma once
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "runtime/backend.h"

namespace glslrun::rt {

class BackendCache {
public:
    struct Key {
        ir::Stage stage;
        Backend backend;  // resolved: Interp or Jit
        Precision precision;
        uint32_t fast_ops;
        bool avx2;  // the vector ISA the code was made for
        auto tie() const { return std::tie(stage, backend, precision, fast_ops, avx2); }
        bool operator<(const Key& o) const { return tie() < o.tie(); }
    };
    // The code for `key`, compiled now if it is the first request.
    const CompiledShader& get(const ir::Shader& shader, const Key& key);
    // Seconds LLVM spent compiling this program's shaders so far.
    double jit_compile_seconds() const;

private:
    mutable std::mutex mutex_;
    std::map<Key, std::unique_ptr<CompiledShader>> shaders_;
    double jit_compile_seconds_ = 0;
};

}  // namespace glslrun::rt
