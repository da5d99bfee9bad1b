// A shader's code cache entry (runtime/jit/cached_shader.h).
#include "runtime/jit/cached_shader.h"

#include <elf.h>
#include <link.h>

#include <cstring>

#include <fmt/format.h>
#include <llvm/Support/BLAKE3.h>
#include <llvm/Support/MemoryBuffer.h>

#include "runtime/fast_kernels.h"

namespace glslrun::rt::jit {

namespace {

// An Instr's fields, without the struct's padding.
constexpr size_t kInstrBytes = 2 + 4 * 7 + 1;

void put_instr(std::string& out, const ir::Instr& in) {
    char bytes[kInstrBytes];
    bytes[0] = char(in.op);
    bytes[1] = char(in.type);
    uint32_t words[7] = {in.dst, in.src[0], in.src[1], in.src[2], in.imm[0], in.imm[1], in.imm[2]};
    std::memcpy(bytes + 2, words, sizeof words);
    bytes[kInstrBytes - 1] = char(in.unmasked);
    out.append(bytes, kInstrBytes);
}

// Registers past the executor's file read as its zero register (call_out_step),
// so no register index of a payload reaches outside it.
std::optional<ir::Instr> get_instr(const char* bytes) {
    ir::Instr in;
    if (uint8_t(bytes[0]) >= uint8_t(ir::Op::Count_) || uint8_t(bytes[1]) > uint8_t(ir::Kind::Bool)) return std::nullopt;
    in.op = ir::Op(uint8_t(bytes[0]));
    in.type = ir::Kind(uint8_t(bytes[1]));
    uint32_t words[7];
    std::memcpy(words, bytes + 2, sizeof words);
    in.dst = words[0];
    for (int i = 0; i < 3; ++i) in.src[i] = words[1 + i], in.imm[i] = words[4 + i];
    in.unmasked = bytes[kInstrBytes - 1] != 0;
    return in;
}

struct BuildIdSearch {
    uintptr_t address = 0;
    std::string hex;
};

// The GNU build ID note among one loaded object's PT_NOTE segments.
std::string build_id_of(const dl_phdr_info& info) {
    for (int i = 0; i < info.dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info.dlpi_phdr[i];
        if (ph.p_type != PT_NOTE) continue;
        const size_t align = ph.p_align == 8 ? 8 : 4;
        auto pad = [&](size_t n) { return (n + align - 1) / align * align; };
        const char* p = reinterpret_cast<const char*>(info.dlpi_addr + ph.p_vaddr);
        const char* end = p + ph.p_memsz;
        while (size_t(end - p) >= sizeof(ElfW(Nhdr))) {
            ElfW(Nhdr) note;
            std::memcpy(&note, p, sizeof note);
            const char* name = p + sizeof note;
            const char* desc = name + pad(note.n_namesz);
            if (desc > end || size_t(end - desc) < note.n_descsz) break;
            if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0) {
                std::string hex;
                for (size_t b = 0; b < note.n_descsz; ++b) hex += fmt::format("{:02x}", uint8_t(desc[b]));
                return hex;
            }
            p = desc + pad(note.n_descsz);
        }
    }
    return {};
}

int find_build_id(dl_phdr_info* info, size_t, void* data) {
    auto* search = static_cast<BuildIdSearch*>(data);
    for (int i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info->dlpi_phdr[i];
        const uintptr_t start = info->dlpi_addr + ph.p_vaddr;
        if (ph.p_type == PT_LOAD && search->address >= start && search->address - start < ph.p_memsz) {
            search->hex = build_id_of(*info);
            return 1;
        }
    }
    return 0;
}

}  // namespace

std::string glslrun_build_id() {
    BuildIdSearch search;
    search.address = reinterpret_cast<uintptr_t>(&glslrun_build_id);
    dl_iterate_phdr(find_build_id, &search);
    return search.hex;
}

std::optional<CodeKey> shader_key(const Engine& engine, const ir::Shader& shader, Precision precision,
                                  uint32_t fast_ops, bool optimised) {
    if (engine.cache_salt.empty()) return std::nullopt;
    std::string bytes = engine.cache_salt;
    bytes += fmt::format("\nshader precision {} fast_ops {} tier {}\n", int(precision), fast_ops, optimised ? 2 : 1);
    append_shader_bytes(bytes, shader);
    return llvm::BLAKE3::hash(llvm::arrayRefFromStringRef(bytes));
}

std::optional<CachedShader> parse_cached_shader(const std::string& payload, Precision precision,
                                                uint32_t fast_ops, bool avx2) {
    uint32_t count = 0;
    if (payload.size() < 4) return std::nullopt;
    std::memcpy(&count, payload.data(), 4);
    if ((payload.size() - 4) / kInstrBytes < count) return std::nullopt;
    CachedShader cached;
    const char* p = payload.data() + 4;
    for (uint32_t i = 0; i < count; ++i, p += kInstrBytes) {
        std::optional<ir::Instr> in = get_instr(p);
        if (!in) return std::nullopt;
        cached.call_outs.push_back({kernel_for(in->op, avx2, precision, fast_ops), *in});
    }
    const size_t used = size_t(p - payload.data());
    if (used == payload.size()) return std::nullopt;  // no code
    cached.object = llvm::MemoryBuffer::getMemBufferCopy(llvm::StringRef(p, payload.size() - used), "glslrun-cached");
    return cached;
}

void ShaderCacheWriter::notifyObjectCompiled(const llvm::Module*, llvm::MemoryBufferRef object) {
    std::string payload;
    const auto count = uint32_t(call_outs_.size());
    payload.append(reinterpret_cast<const char*>(&count), 4);
    for (const CallOut& call : call_outs_) put_instr(payload, call.instr);
    payload += object.getBuffer();
    disk_.store(key_, payload);  // an unwritable cache: the code serves this process only
}

}  // namespace glslrun::rt::jit
