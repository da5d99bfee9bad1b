// The spec-sentence suite: tests/spec/*.cases hold one compile-verdict case
// per rule of the GLSL 1.10 and 1.20 specifications that makes something an
// error or defines a preprocessor or scoping rule, each with valid and
// invalid forms (format: tests/spec/README.md). Every case must get its
// verdict; a failing case names its header line and the compiler's messages.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "helpers.h"

using namespace glslrun;

namespace {

// AcceptedGap: the spec makes it an error, glslrun still compiles it (each
// such case is listed in docs/semantics.md); the case notices the day it
// stops compiling.
enum class Verdict { Pass, Fail, LinkFail, AcceptedGap };

struct SpecCase {
    std::string where;  // file:line of the header
    std::string title;  // section and the sentence's gist
    Stage stage = Stage::Vertex;
    int version = 110;
    Verdict verdict = Verdict::Pass;
    std::string body;
};

// "== §3.3 gist | vert 110 pass" starts a case; the shader follows.
std::vector<SpecCase> parse_cases(const std::filesystem::path& file) {
    std::vector<SpecCase> cases;
    std::ifstream in(file);
    std::string line;
    int lineno = 0;
    while (std::getline(in, line)) {
        ++lineno;
        if (line.rfind("== ", 0) != 0) {
            if (!cases.empty()) cases.back().body += line + "\n";
            continue;
        }
        size_t bar = line.rfind('|');
        INFO(file.filename().string() << ":" << lineno << ": " << line);
        REQUIRE(bar != std::string::npos);
        SpecCase c;
        c.where = file.filename().string() + ":" + std::to_string(lineno);
        c.title = line.substr(3, bar - 3);
        std::istringstream words(line.substr(bar + 1));
        std::string stage, verdict;
        words >> stage >> c.version >> verdict;
        REQUIRE((stage == "vert" || stage == "frag"));
        REQUIRE((verdict == "pass" || verdict == "fail" || verdict == "link-fail" || verdict == "accepted-gap"));
        REQUIRE((c.version == 110 || c.version == 120));
        c.stage = stage == "vert" ? Stage::Vertex : Stage::Fragment;
        c.verdict = verdict == "pass"        ? Verdict::Pass
                    : verdict == "fail"      ? Verdict::Fail
                    : verdict == "link-fail" ? Verdict::LinkFail
                                             : Verdict::AcceptedGap;
        cases.push_back(std::move(c));
    }
    return cases;
}

// "" when the case gets its verdict, else what went wrong.
std::string run_case(const SpecCase& c) {
    ShaderSource src{"case", c.body};
    Status compiled = check_shader(c.stage, src, c.version);
    if (c.verdict == Verdict::Fail)
        return compiled ? "compiled, but the rule makes it an error" : "";
    if (!compiled) return "does not compile:\n" + compiled.error().str();
    if (c.verdict != Verdict::LinkFail) return "";
    CompileOptions options;
    options.default_version = c.version;
    std::vector<ShaderSource> one{src}, none;
    auto linked = c.stage == Stage::Vertex ? Program::compile(one, none, options) : Program::compile(none, one, options);
    return linked ? "linked, but the rule makes it a link error" : "";
}

}  // namespace

TEST_CASE("spec sentences: every case gets its verdict") {
    std::filesystem::path dir = std::filesystem::path(GLSLRUN_SOURCE_DIR) / "tests" / "spec";
    std::map<std::string, std::vector<SpecCase>> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.path().extension() == ".cases") files[entry.path().string()] = parse_cases(entry.path());
    REQUIRE(files.size() >= 5);
    for (const auto& [path, cases] : files) {
        CHECK(cases.size() >= 10);  // a chapter with a handful of cases is a parse problem
        for (const SpecCase& c : cases) {
            std::string problem = run_case(c);
            INFO(c.where << ": " << c.title);
            CHECK(problem == "");
        }
    }
}
