// The JIT's code cache on disk, as Mesa's shader cache: the machine code one
// process compiles is stored under a key, and a later process (or a later
// Program) that needs the same code loads it instead of running LLVM.
//
// The key (runtime/jit/cached_shader.cpp) is a BLAKE3 digest of everything
// the code depends on: the shader's IR (append_shader_bytes), precision and
// Fast classes, the ISA and CPU features LLVM targets, the code-generation
// level, the batch width, LLVM's version and the build ID of the glslrun
// binary that made it (any rebuild has another). An entry is one file,
// written to a temporary name and renamed into place (readers never see a
// partial file, concurrent writers of one key leave one whole entry); its
// header holds the key and a checksum of the rest, and an entry that does not
// match them is ignored, removed and written again. The cache is kept under
// a size cap, per shard: 256 subdirectories by the key's first byte, each
// held to 1/256 of the cap by removing its least recently used entries when
// an entry is written (docs/limits.md).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "glslrun/glslrun.h"
#include "ir/ir.h"

namespace glslrun::rt {

// Where the cache is and how large it may grow (ExecOptions::code_cache_*
// with the environment and the defaults applied); dir empty: no cache.
struct CodeCacheConfig {
    std::string dir;
    uint64_t max_bytes = 0;
    std::string problem;  // a value that could not be used (GLSLRUN_CACHE_MAX_SIZE), for code_cache_status
};
CodeCacheConfig code_cache_config(const ExecOptions& options);

inline constexpr uint64_t kDefaultCodeCacheBytes = uint64_t(256) << 20;
// An entry larger than this is neither written nor read (docs/limits.md).
inline constexpr uint64_t kMaxCodeCacheEntryBytes = uint64_t(64) << 20;
inline constexpr int kCodeCacheShards = 256;

using CodeKey = std::array<uint8_t, 32>;

// One cache directory's entries. Never throws; every failure is a miss, or
// an entry not written.
class DiskCache {
public:
    explicit DiskCache(CodeCacheConfig config) : config_(std::move(config)) {}
    // The payload stored for `key`; nothing where there is none or it is not
    // whole (such an entry is removed). A hit marks the entry recently used.
    std::optional<std::string> load(const CodeKey& key) const;
    // Stores `payload` for `key` (replacing any entry), then keeps the
    // key's shard under its share of the cap. False where it could not be
    // written (an unwritable directory: the caller goes on without it).
    bool store(const CodeKey& key, std::string_view payload) const;
    // The entry's file: DIR/ab/cdef... (the key in hex, its first byte as the shard).
    std::string path_of(const CodeKey& key) const;

private:
    void evict(const std::string& shard, const std::string& keep) const;
    CodeCacheConfig config_;
};

// The bytes that determine a shader's generated code, besides the JIT's own
// settings: every field of the IR that the code generator reads.
void append_shader_bytes(std::string& out, const ir::Shader& shader);

}  // namespace glslrun::rt
