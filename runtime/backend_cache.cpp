// The per-program cache of compiled shaders and Backend::Auto's policy
// (runtime/backend_cache.h).
#include "runtime/backend_cache.h"

#include <algorithm>
#include <bit>
#include <chrono>

#include "ir/passes.h"
#include "runtime/jit/jit.h"
#include "runtime/jit_plugin.h"

namespace glslrun::rt {

namespace {

// A shader's code and the IR it was made from, which the code may refer to
// (the interpreter's does, where the JIT declines it): a specialized copy,
// or a background compile's own copy of the program's.
class OwningShader final : public CompiledShader {
public:
    std::shared_ptr<const ir::Shader> shader;
    std::unique_ptr<CompiledShader> code;
    std::unique_ptr<Executor> instantiate(const ExecParams& params) const override {
        return code->instantiate(params);
    }
};

// An executor that adds the time its runs take, and the lanes they shade,
// to a stage's Meter when it goes (at the end of its draw); untimed, only
// the lanes, to Meter::hot_lanes (the second tier's count: a clock read
// per batch would cost a large frame milliseconds).
class TimedExecutor final : public Executor {
public:
    TimedExecutor(std::unique_ptr<Executor> inner, BackendCache::Meter& meter, bool timed = true)
        : inner_(std::move(inner)), meter_(meter), which_(inner_->runner() == Runner::Jit ? 1 : 0), timed_(timed) {}
    ~TimedExecutor() override {
        if (!timed_) {
            meter_.hot_lanes.fetch_add(lanes_, std::memory_order_relaxed);
            return;
        }
        meter_.nanos[which_].fetch_add(nanos_, std::memory_order_relaxed);
        meter_.lanes[which_].fetch_add(lanes_, std::memory_order_relaxed);
    }
    uint32_t* lanes(ir::Reg r) override { return inner_->lanes(r); }
    bool run(LaneMask live, RunError* error) override {
        lanes_ += uint64_t(std::popcount(live));
        if (!timed_) return inner_->run(live, error);
        const auto start = std::chrono::steady_clock::now();
        const bool ok = inner_->run(live, error);
        nanos_ += uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count());
        return ok;
    }
    LaneMask alive() const override { return inner_->alive(); }
    void skip_lookups(LaneMask lanes) override { inner_->skip_lookups(lanes); }
    Runner runner() const override { return inner_->runner(); }
    void watch_undefined(UndefSink* sink) override { inner_->watch_undefined(sink); }
    bool hold_denormal_mode(bool held) override { return inner_->hold_denormal_mode(held); }

private:
    std::unique_ptr<Executor> inner_;
    BackendCache::Meter& meter_;
    int which_;
    bool timed_;
    uint64_t nanos_ = 0, lanes_ = 0;
};

// Auto compares the backends once the JIT's code has run this long: long
// enough that timer and cache effects are small against it, short enough
// that a JIT slower than the interpreter costs little.
constexpr uint64_t kMeasureNanos = 2'000'000;

// LLVM's expected CPU time for `shader`, in nanoseconds; 0 where the JIT
// does not take it.
uint64_t expected_compile_nanos(const ir::Shader& shader, bool quick_codegen, bool optimised) {
    const JitPlan plan = plan_jit(shader, quick_codegen, optimised);
    return plan.take ? std::max<uint64_t>(1, plan.nanos) : 0;
}

}  // namespace

BackendCache::Slots::Made BackendCache::compile(const ir::Shader& shader, const Key& key,
                                                const std::atomic<bool>* stop, CodeCacheUse cache) {
    Slots::Made made;
    cache.loaded = &made.loaded;
    if (key.specialization.empty()) {
        made.code = compile_shader(shader, key.runner, key.precision, key.fast_ops, key.avx2, &made.seconds,
                                   key.quick_codegen, stop, cache, key.optimised);
        return made;
    }
    const std::vector<uint32_t> read = ir::uniform_words_read(shader);
    std::vector<uint32_t> store(read.empty() ? 0 : read.back() + 1);
    for (size_t i = 0; i < read.size(); ++i) store[read[i]] = key.specialization[i];
    auto specialized = std::make_unique<ir::Shader>(shader);
    const uint32_t approximated = key.precision == Precision::Fast ? key.fast_ops : 0;
    if (!ir::specialize(*specialized, store, approximated).empty()) *specialized = shader;  // a bug: unspecialized
    auto owner = std::make_unique<OwningShader>();
    owner->code = compile_shader(*specialized, key.runner, key.precision, key.fast_ops, key.avx2, &made.seconds,
                                 key.quick_codegen, stop, cache, key.optimised);
    if (!owner->code) return made;  // only_load, and not in the cache
    owner->shader = std::move(specialized);
    made.code = std::move(owner);
    return made;
}

const CompiledShader& BackendCache::get(const ir::Shader& shader, const Key& key, const CodeCacheConfig* cache) {
    return *slots_of(key).get(key, [&](const std::atomic<bool>*) { return compile(shader, key, nullptr, {cache}); });
}

void BackendCache::queue(const ir::Shader& shader, const Key& key, const CodeCacheConfig* cache) {
    Slots& slots = slots_of(key);
    if (slots.requested(key)) return;
    auto copy = std::make_shared<const ir::Shader>(shader);
    auto config = std::make_shared<const CodeCacheConfig>(cache ? *cache : CodeCacheConfig{});
    slots.queue(key, [copy, key, config](const std::atomic<bool>* stop) {
        Slots::Made made = compile(*copy, key, stop, {config.get()});
        auto owner = std::make_unique<OwningShader>();  // the code may refer to the copy
        owner->code = std::move(made.code);
        owner->shader = copy;
        if (owner->code) made.code = std::move(owner);
        return made;
    });
}

// The stage's JIT code from the code cache, at its first draw: where there
// is some, the JIT serves from the start (no interpreted warm-up, no compile).
// Only once the JIT's plugin is loaded: loading LLVM costs more than a short
// render interprets; a longer one loads it when its compile is due, and
// then finds its code in the cache.
bool BackendCache::probe(const ir::Shader& shader, const Key& plain, const CodeCacheConfig* cache) {
    Meter& meter = meters_[size_t(plain.stage)];
    if (meter.probed || !cache || cache->dir.empty() || !jit_plugin_loaded()) return false;
    meter.probed = true;
    Slots::Made made = compile(shader, plain, nullptr, {cache, true});
    if (!made.code || !made.loaded) return false;
    slots_of(plain).put(plain, std::move(made));
    meter.queued.store(true);
    return true;
}

// The second tier is due once the first tier's JIT code has run about as
// long as its compile is expected to take (Auto's rule for the first tier
// too): a long render pays at most about twice the ideal, and a short one
// (a frame, a piglit test) never pays. The time since the JIT's first part
// was timed is its lanes at the timed part's cost per lane.
bool BackendCache::optimise_due(const Meter& meter) {
    const uint64_t nanos = meter.nanos[1].load(), lanes = meter.lanes[1].load();
    if (lanes == 0 || meter.optimise_nanos == 0 || meter.optimise_nanos == Meter::kUnknown) return false;
    const long double spent = (long double)nanos + (long double)meter.hot_lanes.load() * nanos / lanes;
    return spent >= (long double)meter.optimise_nanos;
}

const CompiledShader* BackendCache::optimised(const ir::Shader& shader, const Key& plain,
                                              const CodeCacheConfig* cache, bool may_queue) {
    Meter& meter = meters_[size_t(plain.stage)];
    if (plain.optimised || !plain.specialization.empty()) return nullptr;
    Key key = plain;
    key.optimised = true;
    if (const CompiledShader* code = optimised_->ready(key)) return code;
    if (meter.optimise_queued) return nullptr;
    if (meter.optimise_nanos == Meter::kUnknown)
        meter.optimise_nanos = plan_jit(shader, plain.quick_codegen).optimisable
                                   ? std::max<uint64_t>(1, plan_jit(shader, plain.quick_codegen, true).nanos)
                                   : 0;
    if (meter.optimise_nanos == 0) return nullptr;
    // plan_compile's estimate errs high (3 to 5 times the second tier's
    // time on the corpus's shaders, docs/performance.md); where the first
    // tier was compiled here, its own time at the plan's ratio says better.
    if (!meter.optimise_measured)
        if (std::optional<double> first = slots_->compile_seconds(plain)) {
            meter.optimise_measured = true;
            const double expected = *first * 1e9 / jit::kQuickCodegenShare;
            meter.optimise_nanos = std::max<uint64_t>(1, std::min(meter.optimise_nanos, uint64_t(expected)));
        }
    // An earlier run's code, once the JIT's plugin is loaded (as probe()).
    if (!meter.optimise_probed && cache && !cache->dir.empty() && jit_plugin_loaded()) {
        meter.optimise_probed = true;
        Slots::Made made = compile(shader, key, nullptr, {cache, true});
        if (made.code && made.loaded) {
            optimised_->put(key, std::move(made));
            meter.optimise_queued = true;
            meter.queued.store(true);  // nor the first tier's compile
            return optimised_->ready(key);
        }
    }
    if (!may_queue || !optimise_due(meter)) return nullptr;
    meter.optimise_queued = true;
    queue(shader, key, cache);
    return optimised_->ready(key);  // compiled here, without a thread
}

std::unique_ptr<Executor> BackendCache::watch(std::unique_ptr<Executor> code, const Key& plain) {
    Meter& meter = meters_[size_t(plain.stage)];
    if (code->runner() != Runner::Jit || plain.optimised || !plain.specialization.empty() || meter.optimise_queued ||
        meter.optimise_nanos == 0 || meter.optimise_nanos == Meter::kUnknown)
        return code;
    return std::make_unique<TimedExecutor>(std::move(code), meter, meter.nanos[1].load() < kMeasureNanos);
}

std::unique_ptr<Executor> BackendCache::jit_executor(const ir::Shader& shader, const Key& key,
                                                     const ExecParams& params, const CodeCacheConfig* cache,
                                                     bool tiered) {
    if (!tiered || key.optimised || !key.specialization.empty() || !jit_plugin())
        return get(shader, key, cache).instantiate(params);
    std::unique_lock lock(mutex_);
    if (const CompiledShader* code = optimised(shader, key, cache, true)) {
        lock.unlock();
        return code->instantiate(params);
    }
    lock.unlock();  // a compile here waits on the slot, not on the policy
    std::unique_ptr<Executor> code = get(shader, key, cache).instantiate(params);
    lock.lock();
    return watch(std::move(code), key);
}

std::unique_ptr<Executor> BackendCache::auto_executor(const ir::Shader& shader, const Key& key, const Key& interp,
                                                      const ExecParams& params, const CodeCacheConfig* cache,
                                                      bool tiered) {
    Meter& meter = meters_[size_t(key.stage)];
    const int chosen = meter.choice.load(std::memory_order_relaxed);
    if (chosen == int(Runner::Interp)) return get(shader, interp).instantiate(params);
    std::unique_lock lock(mutex_);
    Key plain = key;
    plain.specialization.clear();
    // The second tier's code where it is made (or in the cache), and queued
    // once the stage is hot and the JIT was kept.
    const CompiledShader* jit =
        tiered && key.specialization.empty() ? optimised(shader, plain, cache, chosen == int(Runner::Jit)) : nullptr;
    const bool first_tier = jit == nullptr;
    if (!meter.queued.load()) probe(shader, plain, cache);
    if (!jit) jit = slots_of(plain).ready(plain);
    if (jit && first_tier && !key.specialization.empty() && chosen == int(Runner::Jit)) {
        // The JIT won: specialize as ExecOptions::jit_specialize_after asks,
        // with the unspecialized code meanwhile.
        if (const CompiledShader* specialized = slots_->ready(key)) jit = specialized;
        else queue(shader, key, cache);
    }
    auto watched = [&](std::unique_ptr<Executor> code) {
        return first_tier && tiered ? watch(std::move(code), key) : std::move(code);
    };
    if (jit) {
        std::unique_ptr<Executor> code = jit->instantiate(params);
        if (code->runner() != Runner::Jit) {
            meter.choice.store(int(Runner::Interp));  // the JIT declined the shader
            return code;
        }
        if (chosen == int(Runner::Jit)) return watched(std::move(code));
        const uint64_t jit_nanos = meter.nanos[1].load(), interp_nanos = meter.nanos[0].load();
        if (jit_nanos < kMeasureNanos) return std::make_unique<TimedExecutor>(std::move(code), meter);
        if (interp_nanos < kMeasureNanos) {
            // Code from the cache (or a tiny stage's) ran before the
            // interpreter had run as long: time the interpreter too.
            lock.unlock();
            return std::make_unique<TimedExecutor>(get(shader, interp).instantiate(params), meter);
        }
        // Per lane: jit_nanos / jit_lanes against interp_nanos / interp_lanes.
        const long double jit_cost = (long double)jit_nanos * (long double)meter.lanes[0].load(),
                          interp_cost = (long double)interp_nanos * (long double)meter.lanes[1].load();
        const Runner keep = jit_cost < interp_cost ? Runner::Jit : Runner::Interp;
        meter.choice.store(int(keep));
        if (keep == Runner::Jit) return watched(std::move(code));
        lock.unlock();
        return get(shader, interp).instantiate(params);
    }
    if (!meter.queued.load()) {
        if (meter.expected_nanos == Meter::kUnknown)
            meter.expected_nanos = expected_compile_nanos(shader, key.quick_codegen, key.optimised);
        if (meter.expected_nanos == 0) {
            meter.choice.store(int(Runner::Interp));  // the JIT does not take it
        } else if (meter.nanos[0].load() >= meter.expected_nanos) {
            meter.queued.store(true);
            queue(shader, plain, cache);
            if (slots_of(plain).ready(plain)) {  // compiled here, without a thread
                lock.unlock();
                return auto_executor(shader, key, interp, params, cache, tiered);
            }
        }
    }
    lock.unlock();
    return std::make_unique<TimedExecutor>(get(shader, interp).instantiate(params), meter);
}

std::vector<uint32_t> BackendCache::specialization(const ir::Shader& shader, const std::vector<uint32_t>& store,
                                                   uint64_t use, uint32_t after) {
    std::lock_guard lock(mutex_);
    Streak& streak = streaks_[size_t(shader.stage)];
    if (!streak.surveyed) streak.read = ir::uniform_words_read(shader), streak.surveyed = true;
    if (streak.read.empty() || after == 0) return {};
    std::vector<uint32_t> words;
    for (uint32_t w : streak.read) words.push_back(w < store.size() ? store[w] : 0);
    if (words != streak.words) {
        streak.words = words;
        streak.draws = 1;
    } else if (use != streak.last_use) {
        ++streak.draws;
    }
    streak.last_use = use;
    return streak.draws >= after ? words : std::vector<uint32_t>{};
}

double BackendCache::jit_compile_seconds() const { return slots_->seconds() + optimised_->seconds(); }

double BackendCache::optimise_seconds() const { return optimised_->seconds(); }

Program::JitCompiles BackendCache::jit_compiles() const {
    Program::JitCompiles first = slots_->compiles(), second = optimised_->compiles();
    return {first.compiled + second.compiled, first.loaded + second.loaded, second.compiled + second.loaded};
}

}  // namespace glslrun::rt
