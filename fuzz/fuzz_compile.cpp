// libFuzzer target: Program::compile on arbitrary text, then a small draw.
// The input is the fragment shader; a NUL byte splits off a vertex shader
// before it. The limits are lowered so that each input runs in milliseconds.
//
// The draw runs on the interpreter, except for one input in 16 (by its
// length), which runs the JIT's code instead. Under Backend::Auto (the
// default) every program would start an LLVM compile whose code a single
// small draw never runs: a third of the time of the inputs that compile.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "glslrun/glslrun.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace glslrun;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<ShaderSource> vs, fs;
    size_t split = text.find('\0');
    if (split != std::string_view::npos) {
        vs.push_back({"fuzz.vert", std::string(text.substr(0, split))});
        text.remove_prefix(split + 1);
    }
    fs.push_back({"fuzz.frag", std::string(text)});
    auto prog = Program::compile(vs, fs);
    if (!prog) return 0;
    prog->exec.threads = 1;
    prog->exec.max_loop_iterations = 1u << 10;
    prog->exec.max_instructions = 1u << 16;
    bool jit = size % 16 == 0 && jit_available();
    prog->exec.backend = jit ? Backend::Jit : Backend::Interp;
    prog->exec.jit_quick_codegen = true;
    Framebuffer fb(8, 8);
    VertexAttrib pos{"gl_Vertex", 4, {-1, -1, 0, 1, 3, -1, 0.5f, 1, -1, 3, -0.5f, 1}};
    VertexAttrib color{"gl_Color", 4, {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1}};
    (void)draw(*prog, GLState{}, fb, Primitive::Triangles, {pos, color}, 3);
    return 0;
}
