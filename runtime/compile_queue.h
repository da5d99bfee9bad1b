// The process's background compiles: one queue, run by one thread, for every
// program's tiered LLVM compiles (runtime/backend_cache.h, the fused
// pipelines of raster/fused/pipeline.h). One thread, not one per
// program stage: hundreds of live programs then cost one thread's stack and
// one compile's memory at a time, and compiles take turns on the JIT's
// engine anyway (runtime/jit/engine.h).
//
// Nothing waits for a background compile: a job holds what it compiles and
// a weak reference to where the code goes, so a program that goes away
// leaves its queued jobs to find it gone. At exit the queued jobs are
// dropped, and the one running gives up at its next phase (`stopping`).
#pragma once
#include <atomic>
#include <functional>

namespace glslrun::rt {

// Queues `job` for the compile thread (started at the first call). False
// where no thread could be started: the caller then compiles itself. A job
// runs with exceptions caught (an allocation failure leaves its code
// uncompiled, and the interpreter serves).
bool submit_compile(std::function<void()> job);

// Set once the process has begun to exit: a compile checks it between its
// phases and gives up.
const std::atomic<bool>& compiles_stopping();

// Registers (again) the exit handler that drops the queued jobs and waits
// for the running one to give up. Exit handlers run in the reverse order of
// their registration, static destructors included: whoever loads code
// whose static destructors a compile uses (the JIT's plugin, and LLVM with
// it) calls this after loading it, so that no compile runs on while they do.
void stop_compiles_before_exit();

// Jobs queued or running (for tests).
size_t compiles_pending();

}  // namespace glslrun::rt
