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
        // A specialized shader's uniform words (those the stage reads, in
        // order: ir::uniform_words_read); empty for the unspecialized one.
        std::vector<uint32_t> specialization = {};
        auto tie() const { return std::tie(stage, backend, precision, fast_ops, avx2, quick_codegen, specialization); }
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
    // The specialization policy (ExecOptions::jit_specialize_after): the
    // words of `store` that `shader` reads once the draws numbered `use`
    // (Program::State::uses) have seen them unchanged `after` times in a
    // row, else empty (the unspecialized shader).
    std::vector<uint32_t> specialization(const ir::Shader& shader, const std::vector<uint32_t>& store, uint64_t use,
                                         uint32_t after);

private:
    const CompiledShader& get_locked(std::unique_lock<std::mutex>& lock, const ir::Shader& shader, const Key& key,
                                     bool wait);
    const CompiledShader& compile_now(const ir::Shader& shader, const Key& key);
    // Runs unlocked; the caller stores the code and its LLVM seconds.
    static std::unique_ptr<CompiledShader> compile(const ir::Shader& shader, const Key& key, double* seconds);
    struct Streak {
        bool surveyed = false;
        std::vector<uint32_t> read;  // the word indices the stage reads
        std::vector<uint32_t> words;  // their values in the current streak
        uint64_t last_use = 0;
        uint32_t draws = 0;
    };
    Streak streaks_[2];  // by ir::Stage

    mutable std::mutex mutex_;
    std::condition_variable compiled_;
    std::map<Key, std::unique_ptr<CompiledShader>> shaders_;
    std::map<Key, bool> compiling_;  // keys whose background compile has started
    std::vector<std::thread> threads_;
    double jit_compile_seconds_ = 0;
};

}  // namespace glslrun::rt
