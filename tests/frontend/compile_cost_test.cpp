// Compile cost that grew faster than the source: each input below took
// exponential or quadratic time before, and must now compile (frontend and
// IR passes, with the verifier) or be refused within a bound far above what
// a linear compile needs, and far below what the old cost was.
#include <sys/resource.h>

#include <ctime>

#include "helpers.h"
#include "ir/flow.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

// The process's peak resident memory so far: its growth across a compile
// bounds what the compile needed from above what earlier cases left.
double peak_mib() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024;
}

// Compiles and runs the IR passes with the verifier after each.
void compile_and_optimize(const std::string& fs) {
    ir::Program p = compile_ok(kPassVs, fs);
    for (ir::Shader* s : {&p.vertex, &p.fragment}) CHECK(ir::optimize(*s, ir::PassOptions{true, 4000, true}) == "");
}

}  // namespace

TEST_CASE("compile cost: 40 structs, each two copies of the one before, stop at the struct member limit") {
    // 1.4 KB whose last struct has 2^40 members: glslang walked the whole
    // member tree at each declaration and never finished.
    std::string fs = "struct S0 { float a; };\n";
    for (int k = 1; k < 40; ++k)
        fs += "struct S" + std::to_string(k) + " { S" + std::to_string(k - 1) + " a; S" + std::to_string(k - 1) + " b; };\n";
    fs += "float f(S39 s) { return 1.0; }\nvoid main() { S39 v; gl_FragColor = vec4(f(v)); }\n";
    double start = cpu_seconds();
    std::string e = compile_error(kPassVs, fs);
    INFO(e);
    // S11 is the first past 4096 members (3 * 2^k - 2), on line 12.
    CHECK(e.find("t.frag:12: error: 'S11' : a struct of more than 4096 members") != std::string::npos);
    CHECK(cpu_seconds() - start < 5);
}

TEST_CASE("compile cost: structs within the member limit still compile, nested 4000 deep or 4096 wide") {
    std::string deep = "struct S0 { float a; };\n";
    for (int k = 1; k < 4000; ++k) deep += "struct S" + std::to_string(k) + " { S" + std::to_string(k - 1) + " s; };\n";
    std::string leaf = "v";
    for (int k = 1; k < 4000; ++k) leaf += ".s";
    leaf += ".a";
    compile_ok(kPassVs, deep + "void main() { S3999 v; " + leaf + " = 1.0; gl_FragColor = vec4(" + leaf + "); }\n");
    std::string wide = "struct W {";
    for (int k = 0; k < 4096; ++k) wide += " float f" + std::to_string(k) + ";";
    compile_ok(kPassVs, wide + " };\nvoid main() { W w; w.f4095 = 1.0; gl_FragColor = vec4(w.f4095); }\n");
    std::string past = wide.substr(0, wide.size()) + " float f4096; };\nvoid main() { gl_FragColor = vec4(1.0); }\n";
    CHECK(compile_error(kPassVs, past).find("t.frag:1: error: 'W' : a struct of more than 4096 members") !=
          std::string::npos);
}

TEST_CASE("compile cost: 12000 sequential if/else optimize in linear time") {
    // copyprop, fold, unroll and the definite-assignment analysis each
    // copied their tables at every if: about 45 s of CPU for this source.
    std::string fs = "uniform float u;\nvoid main() {\n    float x = u;\n";
    for (int k = 0; k < 12000; ++k)
        fs += "    if (x > " + std::to_string(k % 5) + ".5) x = x * 0.5; else x = x + 1.0;\n";
    fs += "    gl_FragColor = vec4(x);\n}\n";
    double start = cpu_seconds();
    compile_and_optimize(fs);
    CHECK(cpu_seconds() - start < 10);
}

TEST_CASE("compile cost: 400 arrays at the per-variable limit stop at the stage's component limit") {
    // Every component becomes a register: this took 3.4 GB for a 1x1 image.
    std::string fs = "uniform int i;\nvoid main() {\n    float x = 0.0;\n";
    for (int k = 0; k < 400; ++k)
        fs += "    float a" + std::to_string(k) + "[65536]; a" + std::to_string(k) + "[i] = x; x += a" +
              std::to_string(k) + "[i + 1];\n";
    fs += "    gl_FragColor = vec4(x);\n}\n";
    double start = cpu_seconds();
    std::string e = compile_error(kPassVs, fs);
    INFO(e);
    // 16 arrays and the other variables fit in 2^20 components; the 16th
    // array (line 19) crosses it with the built-ins and x counted first.
    CHECK(e.find(": error: 'a15' : the stage's variables hold more than 1048576 components together") !=
          std::string::npos);
    CHECK(e.find("t.frag:19:") != std::string::npos);
    CHECK(cpu_seconds() - start < 5);
}

TEST_CASE("compile cost: 1200 nested loops around 700 KB of code optimize in time and memory linear in the source") {
    // Each loop listed its body's writes at every level of nesting, logged
    // them again, and the unroller copied its facts per loop: three nested
    // statements per level took 2.3 GB and 8 s of CPU, 24 ran past two
    // minutes. Now about 1 s and 200 MB.
    std::string body;
    for (int j = 0; j < 24; ++j) body += " x = x * 1.0001 + " + std::to_string(j) + ".5;";
    std::string fs = "uniform float u;\nvoid main() {\n    float x = u;\n";
    for (int k = 0; k < 1200; ++k) {
        std::string i = "i" + std::to_string(k);
        fs += "    for (int " + i + " = 0; " + i + " < 1; ++" + i + ") {" + body + "\n";
    }
    for (int k = 0; k < 1200; ++k) fs += "    }";
    fs += "\n    gl_FragColor = vec4(x);\n}\n";
    double start = cpu_seconds(), peak = peak_mib();
    compile_and_optimize(fs);
    CHECK(cpu_seconds() - start < 20);
    CHECK(peak_mib() - peak < 1024);
}

TEST_CASE("compile cost: more distinct calls than the stage's limit are refused before glslang's link") {
    // glslang's link checks the call graph in quadratic time: 8192 small
    // functions each called from main spent 0.7 s of CPU there.
    std::string fs = "uniform float u;\n";
    for (int k = 0; k < 4200; ++k) fs += "float g" + std::to_string(k) + "(float x) { return x + 1.0; }\n";
    fs += "void main() {\n    float x = u;\n";
    for (int k = 0; k < 4200; ++k) fs += "    x = g" + std::to_string(k) + "(x);\n";
    fs += "    gl_FragColor = vec4(x);\n}\n";
    std::string e = compile_error(kPassVs, fs);
    INFO(e.substr(0, 300));
    // main's call of g4096 (line 4204 + 4096) is the 4097th.
    CHECK(e.find("t.frag:8300: error: 'g4096' : the stage makes more than 4096 distinct calls") !=
          std::string::npos);
}

namespace {

// f0 calls nothing, f<k> calls f<k-1>, main calls f<n-1>: calls nest n deep.
std::string call_chain(int n) {
    std::string fs = "uniform float u;\nfloat f0(float x) { return x * 1.5; }\n";
    for (int k = 1; k < n; ++k)
        fs += "float f" + std::to_string(k) + "(float x) { return f" + std::to_string(k - 1) + "(x) + 1.0; }\n";
    return fs + "void main() {\n    gl_FragColor = vec4(f" + std::to_string(n - 1) + "(u));\n}\n";
}

}  // namespace

TEST_CASE("compile cost: a call chain deeper than the limit is refused at compile time, at the call that crosses it") {
    // 1000 deep: minutes in LLVM, then "call depth exceeded (recursion?)" from the interpreter at run time.
    double start = cpu_seconds();
    std::string e = compile_error(kPassVs, call_chain(1000));
    INFO(e.substr(0, 300));
    // main (line 1002) calls f999, ..., f744 (line 746) calls f743: the 257th call.
    CHECK(e.find("t.frag:746: error: 'f743' : calls nest 1000 deep from main, more than glslrun's limit of 256") !=
          std::string::npos);
    CHECK(cpu_seconds() - start < 5);
    // At the limit: compiles and runs.
    compile_ok(kPassVs, call_chain(256));
    CHECK(compile_error(kPassVs, call_chain(257)).find("calls nest 257 deep") != std::string::npos);
    // A function called along two paths counts by its longest.
    std::string diamond = call_chain(255);
    diamond.insert(diamond.find("void main"), "float g(float x) { return f254(x) + f3(x); }\n");
    diamond.replace(diamond.find("vec4(f254(u))"), 13, "vec4(g(u) + f1(u))");
    compile_ok(kPassVs, diamond);  // 256 deep: main -> g -> f254 -> ... -> f0
    diamond.replace(diamond.find("f254(x) + f3(x)"), 15, "f3(x) + h(x)");
    diamond.insert(diamond.find("float g("), "float h(float x) { return f254(x); }\n");
    CHECK(compile_error(kPassVs, diamond).find("'f0' : calls nest 257 deep") != std::string::npos);
}

TEST_CASE("compile cost: 24000 ifs whose condition folds to a constant are spliced in linear time") {
    // fold replaced each such If by its taken branch in place, moving the
    // rest of the block every time: quadratic (16000 took 4.7 s of CPU).
    std::string fs = "uniform float u;\nvoid main() {\n    float x = u;\n    float k = 2.0;\n";
    for (int i = 0; i < 24000; ++i) fs += "if(k>.5)x*=.5;else x+=1.;\n";
    fs += "    gl_FragColor = vec4(x);\n}\n";
    double start = cpu_seconds();
    ir::Program p = compile_ok(kPassVs, fs);
    CHECK(ir::optimize(p.fragment, ir::PassOptions{true, 4000, true}) == "");
    CHECK(cpu_seconds() - start < 5);
    size_t ifs = 0;
    ir::flow::walk(p.fragment.body, [&](const ir::Node& n) { ifs += n.kind == ir::NodeKind::If; });
    CHECK(ifs == 0);
}
