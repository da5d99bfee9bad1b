// Tiering, the one mechanism of both tiered back ends: a program's compiled
// shaders (runtime/backend_cache.h, Backend::Auto's policy) and its fused
// fragment pipelines (raster/fused/pipeline.h). Each key's code is made once
// for the program's life. A caller that cannot go on without it (Backend::Jit,
// the interpreter's own code) has it made at once; a caller whose policy
// says it is due has it made on the process's compile thread
// (runtime/compile_queue.h) and goes on with what it has (the interpreter,
// the C++ fragment path) until it is ready. When it is due is the caller's
// policy; how it is made, kept and counted is here.
//
// A background job holds what it compiles and a weak reference to the slots,
// so a program that goes away waits for nothing; the first code made for a
// key is the one kept (draws may already run it).
#pragma once
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

#include "glslrun/glslrun.h"
#include "runtime/compile_queue.h"

namespace glslrun::rt {

template <class Key, class Code>
class CodeSlots : public std::enable_shared_from_this<CodeSlots<Key, Code>> {
public:
    // What a compile made: its code (null: the compiler declined the key),
    // LLVM's seconds, whether it came from the code cache.
    struct Made {
        std::unique_ptr<Code> code;
        double seconds = 0;
        bool loaded = false;
    };
    // Runs without the slots' lock. `stop` (null where a caller waits for
    // it) tells a background compile that the process is exiting.
    using Compile = std::function<Made(const std::atomic<bool>* stop)>;

    // Always owned by a shared_ptr: background jobs hold weak references.
    static std::shared_ptr<CodeSlots> make() { return std::shared_ptr<CodeSlots>(new CodeSlots); }

    // `key`'s code, made here where it is not made yet (a background compile
    // still queued included). Callers asking for one key meanwhile wait for
    // this compile rather than make their own.
    const Code* get(const Key& key, const Compile& compile) {
        std::lock_guard lock(mutex_);
        Slot& slot = slots_[key];
        if (!slot.made) {
            slot.requested = true;
            keep(slot, compile(nullptr));
        }
        return slot.code.get();
    }

    // `key`'s code where it is made, else null (and null where the compiler
    // declined it: `made` says which).
    const Code* ready(const Key& key, bool* made = nullptr) const {
        std::lock_guard lock(mutex_);
        auto found = slots_.find(key);
        const bool done = found != slots_.end() && found->second.made;
        if (made) *made = done;
        return done ? found->second.code.get() : nullptr;
    }

    // LLVM's seconds for `key`'s code where a compile made it here (not
    // loaded from the code cache, not declined), else nothing.
    std::optional<double> compile_seconds(const Key& key) const {
        std::lock_guard lock(mutex_);
        auto found = slots_.find(key);
        if (found == slots_.end() || !found->second.code || found->second.loaded || found->second.seconds <= 0)
            return std::nullopt;
        return found->second.seconds;
    }

    // Whether `key`'s code was asked for (made, being made or queued).
    bool requested(const Key& key) const {
        std::lock_guard lock(mutex_);
        auto found = slots_.find(key);
        return found != slots_.end() && found->second.requested;
    }

    // Has `key`'s code made on the compile thread, where nobody asked for it
    // before; here where no thread can be had.
    void queue(const Key& key, Compile compile) {
        {
            std::lock_guard lock(mutex_);
            Slot& slot = slots_[key];
            if (slot.requested) return;
            slot.requested = true;
        }
        std::weak_ptr<CodeSlots> self = this->weak_from_this();
        auto job = [self, key, compile] {
            if (self.expired() || compiles_stopping().load()) return;  // the program is gone, or the process
            Made made = compile(&compiles_stopping());
            std::shared_ptr<CodeSlots> slots = self.lock();
            if (!slots || compiles_stopping().load()) return;
            std::lock_guard lock(slots->mutex_);
            slots->keep(slots->slots_[key], std::move(made));
        };
        if (submit_compile(job)) return;
        Made made = compile(nullptr);
        std::lock_guard lock(mutex_);
        keep(slots_[key], std::move(made));
    }

    // Stores code made elsewhere (the code cache's, found at a first draw) as
    // `key`'s, where it has none; false where it had.
    bool put(const Key& key, Made made) {
        std::lock_guard lock(mutex_);
        Slot& slot = slots_[key];
        const bool kept = !slot.made;
        slot.requested = true;
        keep(slot, std::move(made));
        return kept;
    }

    // Seconds LLVM spent on the slots' compiles so far.
    double seconds() const {
        std::lock_guard lock(mutex_);
        return seconds_;
    }
    // The compiles that ran LLVM, and those that loaded the code cache's code.
    Program::JitCompiles compiles() const {
        std::lock_guard lock(mutex_);
        return compiles_;
    }

private:
    struct Slot {
        bool requested = false;
        bool made = false;
        bool loaded = false;  // from the code cache
        double seconds = 0;  // LLVM's, for the code kept
        std::unique_ptr<Code> code;
    };
    CodeSlots() = default;

    // Counts a compile, and keeps its code where the slot has none yet.
    void keep(Slot& slot, Made made) {
        seconds_ += made.seconds;
        if (made.loaded) ++compiles_.loaded;
        else if (made.seconds > 0) ++compiles_.compiled;
        if (slot.made) return;
        slot.code = std::move(made.code);
        slot.made = true;
        slot.loaded = made.loaded;
        slot.seconds = made.seconds;
    }

    mutable std::mutex mutex_;
    std::map<Key, Slot> slots_;
    double seconds_ = 0;
    Program::JitCompiles compiles_;
};

}  // namespace glslrun::rt
