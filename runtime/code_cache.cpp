// The code cache's files (runtime/code_cache.h) and code_cache_status().
#include "runtime/code_cache.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>  // crc32 (zlib comes with libpng)

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "runtime/jit_plugin.h"

namespace glslrun::rt {

namespace {

// The entry's header: magic, format, the key, the payload's size and CRC-32.
constexpr char kMagic[8] = {'G', 'L', 'S', 'L', 'R', 'U', 'N', 'C'};
constexpr uint32_t kFormat = 1;
constexpr size_t kHeaderBytes = 8 + 4 + 4 + 32 + 8 + 4 + 4;
// A temporary file older than this was left by a process that died while writing.
constexpr time_t kStaleTempSeconds = 3600;

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

// "1048576", "512K", "64M", "1G"; nothing where it is not a size.
std::optional<uint64_t> parse_size(const std::string& s) {
    if (s.empty() || s.size() > 20) return std::nullopt;
    uint64_t n = 0;
    size_t i = 0;
    for (; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i) {
        if (n > (UINT64_MAX - 9) / 10) return std::nullopt;
        n = n * 10 + uint64_t(s[i] - '0');
    }
    if (i == 0) return std::nullopt;
    int shift = 0;
    if (i + 1 == s.size()) {
        const char unit = char(s[i] | 0x20);
        shift = unit == 'k' ? 10 : unit == 'm' ? 20 : unit == 'g' ? 30 : -1;
        if (shift < 0) return std::nullopt;
    } else if (i != s.size()) {
        return std::nullopt;
    }
    if (n > (UINT64_MAX >> shift)) return std::nullopt;
    return n << shift;
}

void put32(std::string& out, uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); }
void put64(std::string& out, uint64_t v) { out.append(reinterpret_cast<const char*>(&v), 8); }
uint32_t get32(const char* p) { uint32_t v; std::memcpy(&v, p, 4); return v; }
uint64_t get64(const char* p) { uint64_t v; std::memcpy(&v, p, 8); return v; }

uint32_t crc_of(std::string_view bytes) {
    uLong crc = crc32(0, nullptr, 0);
    while (!bytes.empty()) {  // crc32 takes at most 4 GiB at a time
        const uInt n = uInt(std::min<size_t>(bytes.size(), 1u << 30));
        crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data()), n);
        bytes.remove_prefix(n);
    }
    return uint32_t(crc);
}

bool write_all(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes.remove_prefix(size_t(n));
    }
    return true;
}

// The whole file, or nothing where it is absent, unreadable or past the limit.
std::optional<std::string> read_file(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::nullopt;
    struct stat st {};
    std::optional<std::string> bytes;
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && uint64_t(st.st_size) <= kHeaderBytes + kMaxCodeCacheEntryBytes) {
        std::string buffer(size_t(st.st_size), '\0');
        size_t got = 0;
        while (got < buffer.size()) {
            const ssize_t n = ::read(fd, buffer.data() + got, buffer.size() - got);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break;
            got += size_t(n);
        }
        if (got == buffer.size()) bytes = std::move(buffer);
    }
    ::close(fd);
    return bytes;
}

void append_block(std::string& out, const ir::Block& block);

void append_instr(std::string& out, const ir::Instr& in) {
    out.push_back(char(in.op));
    out.push_back(char(in.type));
    put32(out, in.dst);
    for (ir::Reg r : in.src) put32(out, r);
    for (uint32_t v : in.imm) put32(out, v);
    out.push_back(char(in.unmasked));
}

void append_string(std::string& out, const std::string& s) {
    put64(out, s.size());
    out += s;
}

void append_node(std::string& out, const ir::Node& node) {
    out.push_back(char(node.kind));
    append_instr(out, node.instr);
    put32(out, node.cond);
    put32(out, node.callee);
    put32(out, uint32_t(node.loc.line));
    put32(out, uint32_t(node.loc.column) | uint32_t(node.loc.source) << 16);
    append_block(out, node.body);
    append_block(out, node.alt);
}

void append_block(std::string& out, const ir::Block& block) {
    put64(out, block.size());
    for (const ir::Node& node : block) append_node(out, node);
}

void append_bindings(std::string& out, const std::vector<ir::Binding>& bindings) {
    put64(out, bindings.size());
    for (const ir::Binding& b : bindings) {
        append_string(out, b.name);
        out.push_back(char(b.kind));
        put32(out, b.first);
        put32(out, b.count);
    }
}

// Fields added to these structs must be added to append_shader_bytes (or
// shown not to reach the generated code): cached code made without them
// would be loaded for IR that differs in them.
static_assert(sizeof(ir::Instr) == 36, "a new ir::Instr field: add it to append_instr");
static_assert(sizeof(ir::SourceLoc) == 8, "a new ir::SourceLoc field: add it to append_node");
static_assert(sizeof(ir::Node) == 104, "a new ir::Node field: add it to append_node");
static_assert(sizeof(ir::Shader) == 232, "a new ir::Shader field: add it to append_shader_bytes");
static_assert(sizeof(ir::Function) == 56 && sizeof(ir::Binding) == 48 && sizeof(ir::UndefSite) == 16,
              "a new field: add it to append_shader_bytes");

}  // namespace

void append_shader_bytes(std::string& out, const ir::Shader& shader) {
    out.push_back(char(shader.stage));
    put64(out, shader.regs.size());
    for (ir::Kind k : shader.regs) out.push_back(char(k));
    append_block(out, shader.prologue);
    append_block(out, shader.body);
    put64(out, shader.functions.size());
    for (const ir::Function& f : shader.functions) {
        append_string(out, f.name);
        append_block(out, f.body);
    }
    append_bindings(out, shader.inputs);
    append_bindings(out, shader.outputs);
    out.push_back(char(shader.uses_derivatives));
    out.push_back(char(shader.uses_discard));
    out.push_back(char(shader.helper_lookups_matter));
    put64(out, shader.sources.size());
    for (const std::string& s : shader.sources) append_string(out, s);
    // The undefined-operation checks' sites (their length bounds an index check).
    put64(out, shader.undef_sites.size());
    for (const ir::UndefSite& site : shader.undef_sites) {
        out.push_back(char(site.op));
        put32(out, uint32_t(site.loc.line));
        put32(out, uint32_t(site.loc.column) | uint32_t(site.loc.source) << 16);
        put32(out, site.length);
    }
    // `variables` (the debugger's names) reach no generated code.
}

CodeCacheConfig code_cache_config(const ExecOptions& options) {
    CodeCacheConfig config;
    const std::string off = env("GLSLRUN_NO_CACHE");
    if (!options.code_cache || (!off.empty() && off != "0")) return config;
    config.dir = options.code_cache_dir;
    if (config.dir.empty()) config.dir = env("GLSLRUN_CACHE_DIR");
    if (config.dir.empty()) {
        // The XDG base directory rules: a relative XDG_CACHE_HOME is ignored.
        const std::string xdg = env("XDG_CACHE_HOME"), home = env("HOME");
        if (!xdg.empty() && xdg[0] == '/') config.dir = xdg + "/glslrun";
        else if (!home.empty()) config.dir = home + "/.cache/glslrun";
    }
    config.max_bytes = options.code_cache_max_bytes;
    if (config.max_bytes == 0) {
        const std::string size = env("GLSLRUN_CACHE_MAX_SIZE");
        const std::optional<uint64_t> parsed = parse_size(size);
        if (!size.empty() && (!parsed || *parsed == 0))
            config.problem = fmt::format("GLSLRUN_CACHE_MAX_SIZE={:?} is not a size (bytes, or a number with K, M or "
                                         "G); the default {} MiB applies",
                                         size, kDefaultCodeCacheBytes >> 20);
        config.max_bytes = parsed && *parsed ? *parsed : kDefaultCodeCacheBytes;
    }
    return config;
}

std::string DiskCache::path_of(const CodeKey& key) const {
    std::string hex;
    for (uint8_t b : key) hex += fmt::format("{:02x}", b);
    return config_.dir + "/" + hex.substr(0, 2) + "/" + hex.substr(2);
}

std::optional<std::string> DiskCache::load(const CodeKey& key) const {
    if (config_.dir.empty()) return std::nullopt;
    const std::string path = path_of(key);
    std::optional<std::string> file = read_file(path);
    if (!file) return std::nullopt;
    const char* p = file->data();
    const bool whole = file->size() >= kHeaderBytes && std::memcmp(p, kMagic, 8) == 0 && get32(p + 8) == kFormat &&
                       std::memcmp(p + 16, key.data(), key.size()) == 0 &&
                       get64(p + 48) == file->size() - kHeaderBytes &&
                       get32(p + 56) == crc_of(std::string_view(*file).substr(kHeaderBytes));
    if (!whole) {
        ::unlink(path.c_str());  // truncated or corrupt: compiled and written again
        return std::nullopt;
    }
    ::utimensat(AT_FDCWD, path.c_str(), nullptr, 0);  // recently used (eviction goes by age); may fail read-only
    return file->substr(kHeaderBytes);
}

bool DiskCache::store(const CodeKey& key, std::string_view payload) const {
    if (config_.dir.empty() || payload.size() > kMaxCodeCacheEntryBytes) return false;
    const std::string path = path_of(key);
    const std::string shard = path.substr(0, path.rfind('/'));
    std::error_code ec;
    std::filesystem::create_directories(shard, ec);
    if (ec) return false;
    std::string header(kMagic, 8);
    put32(header, kFormat);
    put32(header, 0);
    header.append(reinterpret_cast<const char*>(key.data()), key.size());
    put64(header, payload.size());
    put32(header, crc_of(payload));
    put32(header, 0);
    std::string temp = shard + "/.tmp-XXXXXX";
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) return false;
    const bool written = write_all(fd, header) && write_all(fd, payload);
    const bool closed = ::close(fd) == 0;
    // rename() replaces an entry atomically: a reader opens the old file or the new one, whole.
    if (!written || !closed || ::rename(temp.c_str(), path.c_str()) != 0) {
        ::unlink(temp.c_str());
        return false;
    }
    evict(shard, path);
    return true;
}

void DiskCache::evict(const std::string& shard, const std::string& keep) const {
    const uint64_t cap = std::max<uint64_t>(config_.max_bytes / kCodeCacheShards, 1);
    DIR* dir = ::opendir(shard.c_str());
    if (!dir) return;
    struct Entry {
        std::string path;
        uint64_t bytes;
        timespec used;
    };
    std::vector<Entry> entries;
    uint64_t total = 0;
    const time_t now = std::time(nullptr);
    while (const dirent* e = ::readdir(dir)) {
        const std::string name = e->d_name, path = shard + "/" + name;
        struct stat st {};
        if (name == "." || name == ".." || ::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
        if (name.rfind(".tmp-", 0) == 0) {
            if (now - st.st_mtime > kStaleTempSeconds) ::unlink(path.c_str());
            continue;  // another process's write in progress
        }
        total += uint64_t(st.st_size);
        if (path != keep) entries.push_back({path, uint64_t(st.st_size), st.st_mtim});
    }
    ::closedir(dir);
    if (total <= cap) return;
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return a.used.tv_sec != b.used.tv_sec ? a.used.tv_sec < b.used.tv_sec : a.used.tv_nsec < b.used.tv_nsec;
    });
    for (const Entry& e : entries) {
        if (total <= cap) break;
        if (::unlink(e.path.c_str()) == 0) total -= e.bytes;
    }
}

}  // namespace glslrun::rt

namespace glslrun {

CodeCacheStatus code_cache_status(const ExecOptions& options) {
    const rt::CodeCacheConfig config = rt::code_cache_config(options);
    CodeCacheStatus status;
    status.dir = config.dir;
    status.max_bytes = config.max_bytes;
    status.warning = config.problem;
    // Whether the plugin is there, without loading it (runtime/jit_plugin.h): asking costs no LLVM.
    status.enabled = !config.dir.empty() && rt::jit_plugin_present();
    if (!status.enabled) return status;
    std::error_code ec;
    std::filesystem::create_directories(config.dir, ec);
    std::string why = ec ? ec.message() : ::access(config.dir.c_str(), W_OK | X_OK) != 0 ? std::strerror(errno) : "";
    if (!why.empty()) {
        if (!status.warning.empty()) status.warning += "; ";
        status.warning += fmt::format("the code cache directory {} cannot be written ({}): compiled code is not kept "
                                      "for the next run (--cache-dir DIR, or --no-cache)",
                                      config.dir, why);
    }
    return status;
}

}  // namespace glslrun
