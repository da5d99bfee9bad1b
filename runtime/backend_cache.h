// The compiled shaders of one Program, by specialization key: made at the
// first draw that needs them (or on the compile thread: runtime/tiering.h)
// and shared by every worker and later draw; and Backend::Auto's policy,
// which picks for each stage the backend that costs least over the
// program's life.
//
// Auto starts with the interpreter and measures its time. Once a stage has
// spent about as long interpreting as LLVM would take to compile it
// (jit::compile_size), its compile is queued on the process's compile
// thread (runtime/compile_queue.h): a short render never pays for a compile
// it does not use, and a long one pays at most about twice the ideal. When
// the code is ready the next draws run it, timed, and the stage keeps
// whichever backend shaded a lane faster. Backend::Jit compiles at the first
// draw and waits. The images are the same either way (the backends compute
// the same bits).
//
// The JIT's second tier (JitPlan): once a stage's JIT code has run about as
// long as LLVM is expected to take to compile it with every optimization
// (the stage is hot: optimise_due() decides), it is compiled so on the
// compile thread, and the stage's next executors run that code. A short
// render never starts it; the code cache holds it under a key of its own,
// and a later run loads it at the stage's first draw where the JIT's plugin
// is loaded, as the first tier's.
#pragma once
#include <atomic>
#include <memory>
#include <mutex>
#include <tuple>
#include <vector>

#include "runtime/backend_factory.h"
#include "runtime/code_cache.h"
#include "runtime/tiering.h"

namespace glslrun::rt {

class BackendCache {
public:
    struct Key {
        ir::Stage stage;
        Runner runner;
        Precision precision;
        uint32_t fast_ops;
        bool avx2;  // the vector ISA the code was made for
        bool quick_codegen;  // ExecOptions::jit_quick_codegen
        // A specialized shader's uniform words (those the stage reads, in
        // order: ir::uniform_words_read); empty for the unspecialized one.
        std::vector<uint32_t> specialization = {};
        bool optimised = false;  // the JIT's second tier (JitPlan)
        auto tie() const {
            return std::tie(stage, runner, precision, fast_ops, avx2, quick_codegen, specialization, optimised);
        }
        bool operator<(const Key& o) const { return tie() < o.tie(); }
    };
    BackendCache() : slots_(Slots::make()), optimised_(Slots::make()) {}
    BackendCache(const BackendCache&) = delete;
    BackendCache& operator=(const BackendCache&) = delete;
    ~BackendCache() = default;  // waits for nothing: queued compiles find it gone

    // The code for `key`, compiled now where it is not yet (a JIT key waits
    // for LLVM, or loads the code from `cache`, which may be null).
    const CompiledShader& get(const ir::Shader& shader, const Key& key, const CodeCacheConfig* cache = nullptr);
    // Backend::Auto: an executor of `key`'s JIT code where the policy above
    // has chosen it, else of the interpreter's; `interp` is the same key for
    // the interpreter. Where `cache` (may be null) holds the stage's code,
    // the JIT serves from the first draw. `tiered`: JitTier::Tiered (else
    // `key`'s tier alone).
    std::unique_ptr<Executor> auto_executor(const ir::Shader& shader, const Key& key, const Key& interp,
                                            const ExecParams& params, const CodeCacheConfig* cache = nullptr,
                                            bool tiered = true);
    // Backend::Jit: an executor of `key`'s code, compiled now where it is not
    // yet, or of the second tier's where it is made (or in `cache`).
    std::unique_ptr<Executor> jit_executor(const ir::Shader& shader, const Key& key, const ExecParams& params,
                                           const CodeCacheConfig* cache = nullptr, bool tiered = true);
    // Seconds LLVM spent compiling this program's shaders so far, both tiers.
    double jit_compile_seconds() const;
    // Of those, the second tier's (in the background).
    double optimise_seconds() const;
    // Its shaders compiled by LLVM so far, and loaded from the code cache.
    Program::JitCompiles jit_compiles() const;
    // The specialization policy (ExecOptions::jit_specialize_after): the
    // words of `store` that `shader` reads once the draws numbered `use`
    // (Program::State::uses) have seen them unchanged `after` times in a
    // row, else empty (the unspecialized shader).
    std::vector<uint32_t> specialization(const ir::Shader& shader, const std::vector<uint32_t>& store, uint64_t use,
                                         uint32_t after);

    // Auto's measurements of one stage's backends, added to by the timed
    // executors of its draws.
    struct Meter {
        std::atomic<uint64_t> nanos[2] = {}, lanes[2] = {};  // by Runner
        std::atomic<bool> queued{false};  // the JIT's compile is queued or done
        bool probed = false;  // the code cache was asked for the stage's code (under the cache's lock)
        std::atomic<int> choice{-1};      // the Runner kept, once measured; -1 while measuring
        static constexpr uint64_t kUnknown = ~uint64_t(0);
        uint64_t expected_nanos = kUnknown;  // LLVM's expected time (0: not taken); under the cache's lock
        // The second tier's: lanes the first tier's JIT code ran untimed
        // (nanos[1] and lanes[1] time a first part of them), and LLVM's
        // expected time for it (0: it would make the same code; once the
        // first tier was compiled here, that compile's time over
        // jit::kQuickCodegenShare where less). Under the cache's lock but
        // the lanes.
        std::atomic<uint64_t> hot_lanes{0};
        uint64_t optimise_nanos = kUnknown;
        bool optimise_queued = false;  // or done, or loaded from the code cache
        bool optimise_probed = false;  // the code cache was asked for it
        bool optimise_measured = false;  // optimise_nanos from the first tier's measured compile
    };

    Meter& meter(ir::Stage stage) { return meters_[size_t(stage)]; }

private:
    using Slots = CodeSlots<Key, CompiledShader>;
    static Slots::Made compile(const ir::Shader& shader, const Key& key, const std::atomic<bool>* stop = nullptr,
                               CodeCacheUse cache = {});
    // Backend::Auto's first draw of a stage: its code from `cache` (with the
    // lock held); false where it has none.
    bool probe(const ir::Shader& shader, const Key& plain, const CodeCacheConfig* cache);
    // Queues `key`'s compile on the compile thread (or compiles it here where
    // there is none), with a copy of `shader`.
    void queue(const ir::Shader& shader, const Key& key, const CodeCacheConfig* cache);
    // The second tier's code of `plain` (an unspecialized JIT key) where it is
    // made, else null: found in `cache` once the JIT's plugin is loaded,
    // queued once the stage is hot where `may_queue`. With the lock held.
    const CompiledShader* optimised(const ir::Shader& shader, const Key& plain, const CodeCacheConfig* cache,
                                    bool may_queue);
    // Whether the stage's first-tier JIT code has run long enough that its
    // second tier is due (the one place that says when a stage is hot).
    static bool optimise_due(const Meter& meter);
    // `code` (first-tier JIT code of `plain`), timed or counted for
    // optimise_due() while the second tier may still come; with the lock held.
    std::unique_ptr<Executor> watch(std::unique_ptr<Executor> code, const Key& plain);
    struct Streak {
        bool surveyed = false;
        std::vector<uint32_t> read;  // the word indices the stage reads
        std::vector<uint32_t> words;  // their values in the current streak
        uint64_t last_use = 0;
        uint32_t draws = 0;
    };
    Streak streaks_[2];  // by ir::Stage
    Meter meters_[2];    // by ir::Stage

    mutable std::mutex mutex_;  // the policy's: the streaks, a Meter's probed and expected_nanos
    std::shared_ptr<Slots> slots_;
    std::shared_ptr<Slots> optimised_;  // the second tier's code, kept apart to count its LLVM time apart
    Slots& slots_of(const Key& key) const { return key.optimised ? *optimised_ : *slots_; }
};

}  // namespace glslrun::rt
