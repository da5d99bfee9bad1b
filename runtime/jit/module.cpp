// The JIT's LLVM set-up: one ORC LLJIT per process and vector ISA (the
// baseline x86-64 or AVX2, x86-64-v3, chosen as the interpreter chooses its
// kernels, never contracting a * b + c into an FMA), holding each compiled
// shader's code as long as the program's cache keeps the shader; and the
// executor that runs the generated functions over its own register file.
#include "runtime/jit/jit.h"

#include <algorithm>
#include <array>
#include <ctime>
#include <cstdlib>
#include <mutex>
#include <optional>

#include <llvm/ExecutionEngine/JITEventListener.h>
#include <llvm/ExecutionEngine/Orc/ExecutionUtils.h>
#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/RTDyldObjectLinkingLayer.h>
#include <llvm/IR/Verifier.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Transforms/Scalar/ADCE.h>
#include <llvm/Transforms/Scalar/DeadStoreElimination.h>
#include <llvm/Transforms/Scalar/EarlyCSE.h>
#include <llvm/Transforms/Scalar/GVN.h>
#include <llvm/Transforms/Scalar/SROA.h>
#include <llvm/Transforms/Scalar/SimplifyCFG.h>
#include <llvm/Support/Host.h>
#include <llvm/Support/TargetSelect.h>

#include <fmt/format.h>
#include <llvm/Config/llvm-config.h>
#include <llvm/ExecutionEngine/Orc/CompileUtils.h>

#include "runtime/aligned_words.h"
#include "runtime/cpu_features.h"
#include "runtime/jit/cached_shader.h"
#include "runtime/jit/codegen.h"
#include "runtime/jit/engine.h"
#include "runtime/jit/flushed.h"

namespace glslrun::rt::jit {

void initialise_llvm() {
    static std::once_flag once;  // LLVM's target registry is process-wide
    std::call_once(once, [] {
        llvm::InitializeNativeTarget();
        llvm::InitializeNativeTargetAsmPrinter();
        llvm::InitializeNativeTargetAsmParser();  // the ops written as x86 instructions (alu.cpp)
    });
}

llvm::orc::JITTargetMachineBuilder target_for(bool avx2, bool quick) {
    llvm::orc::JITTargetMachineBuilder builder{llvm::Triple(llvm::sys::getProcessTriple())};
    const bool wide = avx2 && avx512();
    builder.setCPU(wide ? "x86-64-v4" : avx2 ? "x86-64-v3" : "x86-64");
    // x86-64-v4 tunes for 256-bit vectors, which would split every register
    // in four again
    if (wide) builder.getFeatures().AddFeature("prefer-256-bit", false);
    builder.setCodeGenOptLevel(quick ? llvm::CodeGenOpt::None : llvm::CodeGenOpt::Default);
    builder.getOptions().AllowFPOpFusion = llvm::FPOpFusion::Strict;
    return builder;
}

bool avx512() { return cpu_has_avx512(); }

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

Engine* Engine::of(bool avx2, bool quick) {
    // Never destroyed: a background compile may still use one while the
    // process exits (runtime/compile_queue.h).
    static Engine* engines = new Engine[4];
    static std::once_flag made[4];
    const int which = int(avx2) * 2 + int(quick);
    Engine& e = engines[which];
    std::call_once(made[which], [&] { e.make(target_for(avx2, quick)); });
    return e.jit ? &e : nullptr;
}

Engine::NewModule Engine::new_module(const char* name) {
    NewModule made{std::make_unique<llvm::LLVMContext>(), nullptr};
    made.module = std::make_unique<llvm::Module>(name, *made.context);
    made.module->setDataLayout(machine->createDataLayout());
    made.module->setTargetTriple(machine->getTargetTriple().str());
    return made;
}

EngineCode::~EngineCode() {
    if (!dylib_) return;
    std::lock_guard hold(engine_->lock);
    llvm::consumeError(engine_->jit->getExecutionSession().removeJITDylib(*dylib_));
}

// A JITDylib of this code's own, which finds the call-outs and the process's
// symbols (libm's) in the engine's main one.
void EngineCode::open(Engine& engine) {
    engine_ = &engine;
    dylib_ = &engine.jit->getExecutionSession().createBareJITDylib("code_" + std::to_string(engine.modules++));
    dylib_->addToLinkOrder(engine.jit->getMainJITDylib());
}

bool EngineCode::add_object(Engine& engine, std::unique_ptr<llvm::MemoryBuffer> object) {
    open(engine);
    auto err = engine.jit->addObjectFile(*dylib_, std::move(object));
    if (!err) return true;
    llvm::consumeError(std::move(err));
    return false;
}

void* EngineCode::lookup(const std::string& name) const {
    auto symbol = engine_->jit->lookup(*dylib_, name);
    if (symbol) return symbol->toPtr<void*>();
    llvm::consumeError(symbol.takeError());
    return nullptr;
}

std::unique_ptr<llvm::MemoryBuffer> compile_object(Engine& engine, llvm::Module& module, llvm::ObjectCache* cache) {
    llvm::orc::SimpleCompiler compiler(*engine.machine, cache);
    auto object = compiler(module);
    if (object) return std::move(*object);
    llvm::consumeError(object.takeError());
    return nullptr;
}

void Engine::make(llvm::orc::JITTargetMachineBuilder target) {
    initialise_llvm();
    auto tm = target.createTargetMachine();
    auto built = llvm::orc::LLJITBuilder().setJITTargetMachineBuilder(target).create();
    if (!tm || !built) {
        if (!tm) llvm::consumeError(tm.takeError());
        if (!built) llvm::consumeError(built.takeError());
        return;
    }
    // The baseline ISA has no rounding instruction: floor and ceil call libm.
    auto process = llvm::orc::DynamicLibrarySearchGenerator::GetForCurrentProcess(
        (*built)->getDataLayout().getGlobalPrefix());
    if (!process) {
        llvm::consumeError(process.takeError());
        return;
    }
    (*built)->getMainJITDylib().addGenerator(std::move(*process));
    const llvm::JITSymbolFlags callable = llvm::JITSymbolFlags::Exported | llvm::JITSymbolFlags::Callable;
    auto defined = (*built)->getMainJITDylib().define(llvm::orc::absoluteSymbols(
        {{(*built)->mangleAndIntern(kRunCallOutSymbol),
          llvm::JITEvaluatedSymbol(llvm::pointerToJITTargetAddress(&run_call_out), callable)},
         {(*built)->mangleAndIntern(kChargeSlowlySymbol),
          llvm::JITEvaluatedSymbol(llvm::pointerToJITTargetAddress(&charge_slowly), callable)}}));
    if (defined) {
        llvm::consumeError(std::move(defined));
        return;
    }
    if (std::getenv("GLSLRUN_JIT_PERF"))
        if (auto* rtdyld = llvm::dyn_cast<llvm::orc::RTDyldObjectLinkingLayer>(&(*built)->getObjLinkingLayer()))
            rtdyld->registerJITEventListener(*llvm::JITEventListener::createPerfJITEventListener());
    const std::string build = glslrun_build_id();
    if (!build.empty())
        cache_salt = fmt::format("glslrun {} build {} llvm {} target {} cpu {} features {} opt {} lanes {}",
                                 GLSLRUN_VERSION_STRING, build, LLVM_VERSION_STRING, (*tm)->getTargetTriple().str(),
                                 (*tm)->getTargetCPU().str(), (*tm)->getTargetFeatureString().str(),
                                 int((*tm)->getOptLevel()), kLanes);
    machine = std::move(*tm);
    jit = std::move(*built);
}

// A short function pipeline, without InstCombine: LLVM 15's InstCombine
// rewrites select(c, x + y, x) as x + select(c, y, -0.0), which flushes a
// denormal x in the lanes the select keeps (the fuzz test's program 70 found
// it), whatever the function's denormal-fp-math says. What is left: masks
// into registers (SROA), redundant register loads and stores of the flat
// register file (EarlyCSE, GVN, DSE), dead code, and the CFG.
void optimise(llvm::Module& module, llvm::TargetMachine& machine) {
    llvm::LoopAnalysisManager loops;
    llvm::FunctionAnalysisManager functions;
    llvm::CGSCCAnalysisManager cgscc;
    llvm::ModuleAnalysisManager modules;
    llvm::PassBuilder builder(&machine);
    builder.registerModuleAnalyses(modules);
    builder.registerCGSCCAnalyses(cgscc);
    builder.registerFunctionAnalyses(functions);
    builder.registerLoopAnalyses(loops);
    builder.crossRegisterProxies(loops, functions, cgscc, modules);
    llvm::FunctionPassManager pipeline;
    pipeline.addPass(llvm::SROAPass());
    pipeline.addPass(llvm::EarlyCSEPass(true));
    pipeline.addPass(llvm::SimplifyCFGPass());
    pipeline.addPass(llvm::GVNPass());
    pipeline.addPass(llvm::DSEPass());
    pipeline.addPass(DropNeedlessFlushes());
    pipeline.addPass(llvm::ADCEPass());
    pipeline.addPass(llvm::SimplifyCFGPass());
    llvm::ModulePassManager module_pipeline;
    module_pipeline.addPass(llvm::createModuleToFunctionPassAdaptor(std::move(pipeline)));
    module_pipeline.run(module, modules);
}

namespace {

class JitShader final : public CompiledShader {
public:
    EngineCode code;  // this shader's functions in the engine's LLJIT
    std::vector<CallOut> call_outs;  // the generated code calls the i-th by its index
    ShaderFn main = nullptr, prologue = nullptr;
    uint32_t reg_count = 0;
    bool gpu_textures = false;  // Fast with its GPU filtering: the units' samplers are bind_gpu_direct()'s

    std::unique_ptr<Executor> instantiate(const ExecParams& params) const override;
};

class JitExecutor final : public Executor {
public:
    JitExecutor(const JitShader& code, const ExecParams& p)
        : code_(code), regs_((size_t(code.reg_count) + 1) * kLanes), uniforms_(p.uniforms), limits_(p.limits),
          share_(p.limits.draw) {
        ctx_.max_loop_iterations = p.limits.max_loop_iterations;
        ctx_.start_budget(UINT64_MAX, nullptr);  // the prologue: straight-line code, as the interpreter's
        ctx_.machine.uniforms = p.uniforms;
        ctx_.machine.textures = p.textures;
        ctx_.machine.regs = regs_.data;
        call_steps_.reserve(code.call_outs.size());
        for (const CallOut& call : code.call_outs) call_steps_.push_back(call_out_step(call, regs_.data, code.reg_count));
        ctx_.call_steps = call_steps_.data();
        lookups_ = tex_lookups(code.call_outs, call_steps_);
        ctx_.lookups = lookups_.data();
        bind_direct_samplers(p.textures, code.gpu_textures, direct_.data());
        ctx_.direct = direct_.data();
        bind_kernels(p.textures, code.gpu_textures, kernels_.data());
        ctx_.kernels = kernels_.data();
        ctx_.tex = run_tex;
        derivatives_ = tex_derivatives(code.call_outs, p.textures, code.gpu_textures);
        ctx_.derivatives = derivatives_.data();
        ir::FlushDenormals ftz;  // as the interpreter's prologue and runs
        code_.prologue(&ctx_, regs_.data, uniforms_, kAllLanes);
    }
    uint32_t* lanes(ir::Reg r) override {
        return regs_.data + size_t(r == ir::kNoReg || r >= code_.reg_count ? code_.reg_count : r) * kLanes;
    }
    bool run(LaneMask live, RunError* error) override {
        std::optional<ir::FlushDenormals> ftz;
        if (!held_) ftz.emplace();
        ctx_.start_budget(limits_.max_instructions, limits_.cancel, share_.active() ? &share_ : nullptr);
        Failure failure = Failure(code_.main(&ctx_, regs_.data, uniforms_, live));
        // What the run left unreported counts after a failure too (as the interpreter's).
        if (!ctx_.report(ctx_.next_cancel_poll + ctx_.credit) && failure == Failure::None)
            failure = Failure::DrawBudget;
        if (failure == Failure::None) return true;
        if (error) {
            error->line = failure == Failure::DrawBudget ? 0 : ctx_.error_line;
            error->message = failure == Failure::LoopCap        ? limits_.loop_cap_message()
                             : failure == Failure::Instructions ? limits_.instructions_message()
                             : failure == Failure::Cancelled    ? RunLimits::kCancelledMessage
                             : failure == Failure::DrawBudget   ? share_.message(ctx_.stop)
                                                                : "call to a missing function";
        }
        return false;
    }
    LaneMask alive() const override { return ctx_.alive; }
    void skip_lookups(LaneMask lanes) override { ctx_.machine.lookups = ~lanes; }
    Runner runner() const override { return Runner::Jit; }
    void watch_undefined(UndefSink* sink) override { ctx_.machine.undef = sink; }
    bool hold_denormal_mode(bool held) override {
        held_ = held;
        return true;
    }

private:
    const JitShader& code_;
    AlignedWords<uint32_t> regs_;
    const uint32_t* uniforms_;
    RunLimits limits_;
    BudgetShare share_;
    std::vector<Step<uint32_t>> call_steps_;
    std::vector<BatchLookup> lookups_;
    std::vector<uint8_t> derivatives_;  // ctx_.derivatives
    std::array<DirectSampler, kDirectSlots> direct_;
    std::array<BoundKernel, kKernelSlots> kernels_;
    Context ctx_;
    bool held_ = false;  // the caller holds ir::FlushDenormals around run()
};

std::unique_ptr<Executor> JitShader::instantiate(const ExecParams& params) const {
    return std::make_unique<JitExecutor>(*this, params);
}

// Links `object` into `code` and finds its two functions; false where LLVM refused it.
bool link(Engine& engine, JitShader& code, std::unique_ptr<llvm::MemoryBuffer> object) {
    if (!object || !code.code.add_object(engine, std::move(object))) return false;
    code.main = reinterpret_cast<ShaderFn>(code.code.lookup("glslrun_main"));
    code.prologue = reinterpret_cast<ShaderFn>(code.code.lookup("glslrun_prologue"));
    return code.main && code.prologue;
}

// `shader`'s code from the code cache; null where it has none (or none
// that links: it is then compiled and stored anew).
std::unique_ptr<JitShader> load(Engine& engine, const DiskCache& disk, const CodeKey& key, const ir::Shader& shader,
                                Precision precision, uint32_t fast_ops, bool avx2) {
    std::optional<std::string> payload = disk.load(key);
    if (!payload) return nullptr;
    std::optional<CachedShader> cached = parse_cached_shader(*payload, precision, fast_ops, avx2);
    if (!cached) return nullptr;
    auto code = std::make_unique<JitShader>();  // before the lock: its destructor takes it
    std::lock_guard hold(engine.lock);
    code->reg_count = uint32_t(shader.regs.size());
    code->gpu_textures = precision == Precision::Fast && (fast_ops & kFastTexture);
    code->call_outs = std::move(cached->call_outs);
    if (link(engine, *code, std::move(cached->object))) return code;
    return nullptr;
}

}  // namespace

std::unique_ptr<CompiledShader> compile(const ir::Shader& shader, Precision precision, uint32_t fast_ops,
                                        bool avx2, bool quick_codegen, CompileStats* stats) {
    const bool optimised = stats && stats->optimised;
    const JitPlan plan = plan_compile(shader, quick_codegen, optimised);
    if (precision == Precision::Reference || !plan.take) return nullptr;
    quick_codegen = plan.quick;
    auto stopped = [&] { return stats && stats->stop && stats->stop->load(std::memory_order_relaxed); };
    const double start = thread_cpu_seconds();
    Engine* engine = Engine::of(avx2, quick_codegen);
    if (!engine) return nullptr;
    std::optional<DiskCache> disk;
    std::optional<CodeKey> key;
    if (stats && stats->cache && !stats->cache->dir.empty()) key = shader_key(*engine, shader, precision, fast_ops, optimised);
    if (key) {
        disk.emplace(*stats->cache);
        if (auto loaded = load(*engine, *disk, *key, shader, precision, fast_ops, avx2)) {
            stats->loaded = true;
            stats->seconds = thread_cpu_seconds() - start;
            return loaded;
        }
    }
    if (stats && stats->only_load) return nullptr;
    auto code = std::make_unique<JitShader>();  // before the lock: its destructor takes it
    std::lock_guard hold(engine->lock);
    code->reg_count = uint32_t(shader.regs.size());
    code->gpu_textures = precision == Precision::Fast && (fast_ops & kFastTexture);

    // Its own names: the code lives in a JITDylib of its own (EngineCode).
    Engine::NewModule made = engine->new_module("shader");
    llvm::Module& module = *made.module;
    {
        Emitter emitter(*made.context, module, shader, precision, fast_ops, avx2, code->call_outs);
        emitter.define("glslrun_main", shader.body);
        emitter.define("glslrun_prologue", shader.prologue);
        emitter.define_functions();
    }
    if (stopped() || llvm::verifyModule(module, &llvm::errs())) return nullptr;
    // GLSLRUN_JIT_DUMP=1 prints the module before and after optimization (a debugging aid).
    const bool dump = std::getenv("GLSLRUN_JIT_DUMP") != nullptr;
    if (dump) module.print(llvm::errs(), nullptr);
    optimise(module, *engine->machine);
    if (dump) module.print(llvm::errs(), nullptr);
    if (stopped()) return nullptr;
    std::optional<ShaderCacheWriter> writer;
    if (key) writer.emplace(*disk, *key, code->call_outs);
    if (!link(*engine, *code, compile_object(*engine, module, writer ? &*writer : nullptr)) || stopped())
        return nullptr;
    if (stats) stats->seconds = thread_cpu_seconds() - start;
    return code;
}

}  // namespace glslrun::rt::jit
