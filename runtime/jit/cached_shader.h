// A shader's entry in the code cache (runtime/code_cache.h): its key, and
// the payload: the call-outs the code calls by index (runtime/jit/context.h),
// then the machine code.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <llvm/ExecutionEngine/ObjectCache.h>

#include "runtime/code_cache.h"
#include "runtime/jit/context.h"
#include "runtime/jit/engine.h"

namespace glslrun::rt::jit {

// The key of `shader`'s code from `engine` in `precision` with Fast's
// `fast_ops`, of the JIT's first tier or the `optimised` one (whose code
// may differ in more than the engine's code-generation level); nothing
// where the engine has no cache salt.
std::optional<CodeKey> shader_key(const Engine& engine, const ir::Shader& shader, Precision precision,
                                  uint32_t fast_ops, bool optimised);

// A cached shader: its call-outs with their kernels picked for (precision,
// fast_ops, avx2) and its machine code; nothing where the payload is not
// one (it was checked against its key and checksum; this is against
// garbage all the same).
struct CachedShader {
    std::vector<CallOut> call_outs;
    std::unique_ptr<llvm::MemoryBuffer> object;
};
std::optional<CachedShader> parse_cached_shader(const std::string& payload, Precision precision,
                                                uint32_t fast_ops, bool avx2);

// LLVM's object cache hook for one shader's compile: stores the code, with
// `call_outs`, under `key` when LLVM has made it. It never supplies code
// (the cache is read before any LLVM work).
class ShaderCacheWriter final : public llvm::ObjectCache {
public:
    ShaderCacheWriter(const DiskCache& disk, const CodeKey& key, const std::vector<CallOut>& call_outs)
        : disk_(disk), key_(key), call_outs_(call_outs) {}
    void notifyObjectCompiled(const llvm::Module* module, llvm::MemoryBufferRef object) override;
    std::unique_ptr<llvm::MemoryBuffer> getObject(const llvm::Module*) override { return nullptr; }

private:
    const DiskCache& disk_;
    CodeKey key_;
    const std::vector<CallOut>& call_outs_;
};

// The build ID of the binary that holds glslrun's JIT, in hex; empty where it has none.
std::string glslrun_build_id();

}  // namespace glslrun::rt::jit
