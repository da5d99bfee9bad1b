// The JIT's code cache on disk (runtime/code_cache.h): entries round-trip,
// a corrupt, truncated or misplaced entry is a miss (removed, never loaded),
// concurrent processes writing one key leave a whole entry, the size cap
// evicts the least recently used, an unwritable directory is no error; and
// through the JIT: a second program (or process) with the same code
// compiles nothing, the images are the same bits with and without the
// cache and on the interpreter, another precision or ISA is another key,
// and Backend::Auto runs cached code from its first draw.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "runtime/backend_factory.h"
#include "runtime/code_cache.h"
#include "runtime/jit_plugin.h"
#include "runtime/interp_kernels.h"
#include "runtime/program_state.h"

using namespace glslrun;
namespace fs = std::filesystem;

namespace {

// A fresh directory under the system's temporary one, removed at the end:
// no test touches the user's real cache.
struct TempDir {
    std::string path;
    TempDir() {
        std::string pattern = (fs::temp_directory_path() / "glslrun-cache-test-XXXXXX").string();
        REQUIRE(::mkdtemp(pattern.data()) != nullptr);
        path = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        fs::permissions(path, fs::perms::owner_all, ec);
        fs::remove_all(path, ec);
    }
};

rt::CodeKey key_of(uint8_t first, uint8_t second) {
    rt::CodeKey key{};
    key[0] = first;
    key[1] = second;
    return key;
}

std::vector<std::string> entries(const std::string& dir) {
    std::vector<std::string> found;
    if (!fs::exists(dir)) return found;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) found.push_back(e.path().string());
    return found;
}

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_all(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

TEST_CASE("code cache: an entry round-trips; a damaged one is a miss and goes", "[runtime][code_cache]") {
    TempDir dir;
    const rt::DiskCache cache({dir.path, rt::kDefaultCodeCacheBytes, ""});
    const rt::CodeKey key = key_of(0xab, 1);
    CHECK_FALSE(cache.load(key));
    const std::string payload = "call-outs and machine code \0 with a zero byte";
    REQUIRE(cache.store(key, payload));
    CHECK(cache.path_of(key).starts_with(dir.path + "/ab/01"));
    REQUIRE(cache.load(key) == payload);
    const std::string whole = read_all(cache.path_of(key));

    SECTION("a flipped bit") {
        std::string bad = whole;
        bad[bad.size() - 3] ^= 4;
        write_all(cache.path_of(key), bad);
    }
    SECTION("truncated") { write_all(cache.path_of(key), whole.substr(0, whole.size() - 1)); }
    SECTION("only part of the header") { write_all(cache.path_of(key), whole.substr(0, 20)); }
    SECTION("empty") { write_all(cache.path_of(key), ""); }
    SECTION("longer than its header says") { write_all(cache.path_of(key), whole + "x"); }
    SECTION("another key's entry in its place") {
        const rt::CodeKey other = key_of(0xab, 2);
        REQUIRE(cache.store(other, payload));
        write_all(cache.path_of(key), read_all(cache.path_of(other)));
    }
    CHECK_FALSE(cache.load(key));
    CHECK_FALSE(fs::exists(cache.path_of(key)));  // removed, to be written again
    REQUIRE(cache.store(key, payload));
    CHECK(cache.load(key) == payload);
}

TEST_CASE("code cache: concurrent processes writing one key leave a whole entry", "[runtime][code_cache]") {
    TempDir dir;
    const rt::DiskCache cache({dir.path, rt::kDefaultCodeCacheBytes, ""});
    const rt::CodeKey key = key_of(7, 7);
    // Large enough that a write takes several system calls' worth of time.
    std::string payload(1 << 20, '\0');
    for (size_t i = 0; i < payload.size(); ++i) payload[i] = char(i * 2654435761u >> 13);
    std::vector<pid_t> children;
    for (int c = 0; c < 4; ++c) {
        const pid_t pid = ::fork();
        REQUIRE(pid >= 0);
        if (pid == 0) {
            int status = 0;
            for (int i = 0; i < 40; ++i) {
                if (!cache.store(key, payload)) status = 1;
                // A reader sees the whole payload or nothing: never part of one.
                if (auto got = cache.load(key); got && *got != payload) status = 2;
            }
            ::_exit(status);
        }
        children.push_back(pid);
    }
    for (pid_t pid : children) {
        int status = 0;
        REQUIRE(::waitpid(pid, &status, 0) == pid);
        CHECK(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 0);
    }
    CHECK(cache.load(key) == payload);
    CHECK(entries(dir.path).size() == 1);  // no temporary file left behind
}

TEST_CASE("code cache: the size cap evicts the least recently used entries", "[runtime][code_cache]") {
    TempDir dir;
    // 256 shards: a 256 KiB cap gives each 1 KiB, room for two 400-byte entries.
    const rt::DiskCache cache({dir.path, 256 * 1024, ""});
    const std::string payload(400, 'x');
    const rt::CodeKey a = key_of(3, 1), b = key_of(3, 2), c = key_of(3, 3), elsewhere = key_of(4, 1);
    REQUIRE(cache.store(a, payload));
    REQUIRE(cache.store(elsewhere, payload));
    ::usleep(20000);  // file times of a coarse file system apart
    REQUIRE(cache.store(b, payload));
    ::usleep(20000);
    REQUIRE(cache.load(a));  // a is now the more recently used
    ::usleep(20000);
    REQUIRE(cache.store(c, payload));
    CHECK(cache.load(a));
    CHECK_FALSE(cache.load(b));
    CHECK(cache.load(c));
    CHECK(cache.load(elsewhere));  // another shard: untouched
    // An entry larger than its shard's share is still kept (the newest).
    const std::string large(4096, 'y');
    REQUIRE(cache.store(b, large));
    CHECK(cache.load(b) == large);
    CHECK_FALSE(cache.load(a));
    CHECK_FALSE(cache.load(c));
}

TEST_CASE("code cache: a directory that cannot be written is no error", "[runtime][code_cache]") {
    TempDir dir;
    // Under a regular file: no directory can be made there, whoever runs the test (root too).
    write_all(dir.path + "/file", "x");
    const rt::DiskCache cache({dir.path + "/file/cache", rt::kDefaultCodeCacheBytes, ""});
    CHECK_FALSE(cache.store(key_of(1, 1), "payload"));
    CHECK_FALSE(cache.load(key_of(1, 1)));
    ExecOptions options;
    options.code_cache_dir = dir.path + "/file/cache";
    const CodeCacheStatus status = code_cache_status(options);
    CHECK(status.dir == options.code_cache_dir);
    if (jit_available()) {
        CHECK(status.enabled);
        CHECK_THAT(status.warning, Catch::Contains("cannot be written"));
    }
    options.code_cache_dir = dir.path + "/fine";
    CHECK(code_cache_status(options).warning.empty());
}

TEST_CASE("code cache: the directory and size from options, environment and defaults", "[runtime][code_cache]") {
    // ctest sets GLSLRUN_CACHE_DIR for every test; this test sets its own values and restores them.
    struct Saved {
        std::string name;
        std::optional<std::string> value;
    };
    std::vector<Saved> saved;
    for (const char* name : {"GLSLRUN_NO_CACHE", "GLSLRUN_CACHE_DIR", "XDG_CACHE_HOME", "HOME", "GLSLRUN_CACHE_MAX_SIZE"}) {
        const char* v = std::getenv(name);
        saved.push_back({name, v ? std::optional<std::string>(v) : std::nullopt});
        ::unsetenv(name);
    }
    ExecOptions options;
    ::setenv("HOME", "/home/someone", 1);
    CHECK(rt::code_cache_config(options).dir == "/home/someone/.cache/glslrun");
    ::setenv("XDG_CACHE_HOME", "relative/ignored", 1);
    CHECK(rt::code_cache_config(options).dir == "/home/someone/.cache/glslrun");
    ::setenv("XDG_CACHE_HOME", "/xdg", 1);
    CHECK(rt::code_cache_config(options).dir == "/xdg/glslrun");
    ::setenv("GLSLRUN_CACHE_DIR", "/env/cache", 1);
    CHECK(rt::code_cache_config(options).dir == "/env/cache");
    options.code_cache_dir = "/option/cache";
    CHECK(rt::code_cache_config(options).dir == "/option/cache");
    CHECK(rt::code_cache_config(options).max_bytes == rt::kDefaultCodeCacheBytes);
    ::setenv("GLSLRUN_CACHE_MAX_SIZE", "64M", 1);
    CHECK(rt::code_cache_config(options).max_bytes == uint64_t(64) << 20);
    ::setenv("GLSLRUN_CACHE_MAX_SIZE", "12 apples", 1);
    CHECK(rt::code_cache_config(options).max_bytes == rt::kDefaultCodeCacheBytes);
    CHECK_THAT(rt::code_cache_config(options).problem, Catch::Contains("GLSLRUN_CACHE_MAX_SIZE"));
    options.code_cache_max_bytes = 1000;
    CHECK(rt::code_cache_config(options).max_bytes == 1000);
    ::setenv("GLSLRUN_NO_CACHE", "1", 1);
    CHECK(rt::code_cache_config(options).dir.empty());
    ::setenv("GLSLRUN_NO_CACHE", "0", 1);
    CHECK_FALSE(rt::code_cache_config(options).dir.empty());
    options.code_cache = false;
    CHECK(rt::code_cache_config(options).dir.empty());
    for (const Saved& s : saved) {
        if (s.value) ::setenv(s.name.c_str(), s.value->c_str(), 1);
        else ::unsetenv(s.name.c_str());
    }
}

namespace {

constexpr const char* kVertex = "varying vec2 p;\nvoid main() { p = gl_Vertex.xy; gl_Position = gl_Vertex; }\n";
// Call-outs (sin, pow, an indexed array) and a loop, so that the cached code
// calls the interpreter's kernels and charges the budget.
constexpr const char* kFragment =
    "varying vec2 p;\nuniform float k[3];\n"
    "void main() {\n"
    "  float s = 0.0;\n"
    "  for (int i = 0; i < 3; ++i) s += sin(p.x * k[i]) * pow(abs(p.y) + 0.5, k[int(mod(float(i) + 1.0, 3.0))]);\n"
    "  gl_FragColor = vec4(s, p, 1.0);\n"
    "}\n";

struct Render {
    std::vector<float> pixels;
    Program::JitCompiles compiles;
};

// A 32x32 float image of a full-screen triangle pair.
Render render(Backend backend, Precision precision, const std::string& cache_dir, bool cache = true) {
    auto program = Program::compile({{"cache.vert", kVertex}}, {{"cache.frag", kFragment}});
    REQUIRE(program);
    program->exec.backend = backend;
    program->exec.precision = precision;
    program->exec.threads = 1;
    program->exec.code_cache = cache;
    program->exec.code_cache_dir = cache_dir;
    const float k[3] = {3.0f, 1.5f, 2.25f};
    REQUIRE(program->set_uniform("k", Span<const float>(k, 3)));
    Framebuffer fb(32, 32, true);
    const std::vector<float> quad = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    REQUIRE(draw(*program, GLState{}, fb, Primitive::Triangles, {{"gl_Vertex", 2, quad}}, 6));
    auto colors = fb.color_data<float>();
    return {std::vector<float>(colors.begin(), colors.end()), program->jit_compiles()};
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("code cache: a second program compiles nothing, with the same bits", "[runtime][code_cache]") {
    if (!jit_available()) return;
    TempDir dir;
    const Render interp = render(Backend::Interp, Precision::Precise, dir.path);
    CHECK(entries(dir.path).empty());
    const Render uncached = render(Backend::Jit, Precision::Precise, dir.path, false);
    CHECK(uncached.compiles.compiled == 2);
    CHECK(entries(dir.path).empty());

    const Render first = render(Backend::Jit, Precision::Precise, dir.path);
    CHECK(first.compiles.compiled == 2);
    CHECK(first.compiles.loaded == 0);
    CHECK(entries(dir.path).size() == 2);
    const Render second = render(Backend::Jit, Precision::Precise, dir.path);
    CHECK(second.compiles.compiled == 0);
    CHECK(second.compiles.loaded == 2);
    CHECK(same_bits(second.pixels, first.pixels));
    CHECK(same_bits(second.pixels, uncached.pixels));
    CHECK(same_bits(second.pixels, interp.pixels));

    // Backend::Auto takes the cached code at its first draw (the plugin is loaded: the renders above
    // loaded it): no compile, no warm-up.
    REQUIRE(rt::jit_plugin_loaded());
    const Render automatic = render(Backend::Auto, Precision::Precise, dir.path);
    CHECK(automatic.compiles.compiled == 0);
    CHECK(automatic.compiles.loaded == 2);
    CHECK(same_bits(automatic.pixels, interp.pixels));

    // Another precision is another key; then it is cached too.
    const Render fast = render(Backend::Jit, Precision::Fast, dir.path);
    CHECK(fast.compiles.compiled == 2);
    CHECK(entries(dir.path).size() == 4);
    CHECK(render(Backend::Jit, Precision::Fast, dir.path).compiles.loaded == 2);
    CHECK(same_bits(render(Backend::Interp, Precision::Fast, dir.path).pixels, fast.pixels));

    // Every entry damaged: compiled again, written again, the same bits.
    for (const std::string& path : entries(dir.path)) {
        std::string bytes = read_all(path);
        bytes[bytes.size() / 2] ^= 1;
        write_all(path, bytes);
    }
    const Render repaired = render(Backend::Jit, Precision::Precise, dir.path);
    CHECK(repaired.compiles.compiled == 2);
    CHECK(same_bits(repaired.pixels, interp.pixels));
    CHECK(render(Backend::Jit, Precision::Precise, dir.path).compiles.loaded == 2);
}

TEST_CASE("code cache: the vector ISA is part of the key", "[runtime][code_cache]") {
    if (!jit_available() || !rt::cpu_has_avx2()) return;
    TempDir dir;
    auto program = Program::compile({{"cache.vert", kVertex}}, {{"cache.frag", kFragment}});
    REQUIRE(program);
    ExecOptions options;
    options.code_cache_dir = dir.path;
    const rt::CodeCacheConfig config = rt::code_cache_config(options);
    const ir::Shader& shader = state_of(*program).ir.fragment;
    auto compile = [&](bool avx2) {
        bool loaded = false;
        double seconds = 0;
        auto code = rt::compile_shader(shader, rt::Runner::Jit, Precision::Precise, rt::kAllFastOps, avx2, &seconds,
                                       false, nullptr, {&config, false, &loaded});
        REQUIRE(code);
        return loaded;
    };
    CHECK_FALSE(compile(true));
    CHECK_FALSE(compile(false));  // baseline x86-64: other CPU features, another key
    CHECK(entries(dir.path).size() == 2);
    CHECK(compile(true));
    CHECK(compile(false));
}
