// glslrun's IR: scalarized virtual registers with structured control flow.
//
// - Every value is a scalar register of kind f32, i32 or bool. A vec4 is four
//   registers; a mat3 is three columns of three registers; arrays and structs
//   are flattened. A GLSL variable occupies a *contiguous* register range, so
//   dynamic indexing (load_ind/store_ind) can address it as base + i * stride.
// - Registers are not SSA: a register may be written many times. Writes inside
//   divergent control flow only affect the active lanes.
// - Control flow is structured (Mesa NIR style): If and Loop nodes own nested
//   blocks; Break, Continue, Return and Discard are nodes, executed by masking
//   lanes off (runtime/exec_mask.h).
// - GLSL forbids recursion, so every function has a static frame: its
//   parameters, locals and return value are ordinary registers of the shader.
//   A Call node runs the callee's body; the caller copies arguments in and
//   out/inout parameters back with mov instructions around it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace glslrun::ir {

using Reg = uint32_t;
inline constexpr Reg kNoReg = 0xffffffffu;

enum class Kind : uint8_t { F32, I32, Bool };
const char* kind_name(Kind k);

enum class Op : uint8_t {
#define OP(name, arity, res, opnd, kind, fast, props, expr) name,
#include "ir/opcodes.def"
#undef OP
    Count_
};

enum class OpKind : uint8_t { Alu, Special };
// Precision::Fast's class of an op (the table's `fast` column): Exact ops
// keep their Precise semantics in Fast; each other class has approximate
// kernels, which rt::FastOps switches on class by class.
// Fma is 6, bit 5: bit 4 is the texture lookups' (rt::kFastTexture), which no
// op of the table carries.
enum class FastClass : uint8_t { Exact, Rsqrt, ExpLog, Pow, SinCos, Fma = 6 };
// A class as a mask bit (rt::FastOps): 0 for Exact, else bit c - 1.
constexpr uint32_t fast_class_bit(FastClass c) { return c == FastClass::Exact ? 0u : 1u << (uint32_t(c) - 1); }
// Operand/result type classes of the table: F, I, B, T (instruction type), X.
enum class TypeClass : uint8_t { F, I, B, T, X };

// The table's `props` column: what an op is (ir/opcodes.def says what each
// means), as bits of OpInfo::props.
enum class OpProp : uint16_t {
    Pure = 1u << 0,
    Commutative = 1u << 1,
    Libm = 1u << 2,
    CrossLane = 1u << 3,
    ReadsRange = 1u << 4,
    WritesRange = 1u << 5,
    Texture = 1u << 6,
    Effect = 1u << 7,
    Blends = 1u << 8,
    CallOut = 1u << 9,
};

struct OpInfo {
    const char* name;
    int arity;
    TypeClass result;
    TypeClass operand;
    OpKind kind;
    FastClass fast;
    uint16_t props;  // OpProp bits
};
const OpInfo& op_info(Op op);
// Whether the table gives `op` the property `p`.
inline bool has(Op op, OpProp p) { return (op_info(op).props & uint16_t(p)) != 0; }

struct Instr {
    Op op = Op::mov;
    Kind type = Kind::F32;  // kind of dst (for store_ind: kind of the stored value)
    Reg dst = kNoReg;
    Reg src[3] = {kNoReg, kNoReg, kNoReg};
    uint32_t imm[3] = {0, 0, 0};
    // Set by ir/regalloc.cpp: no lane can read what dst held before, so the
    // interpreter may write every lane instead of blending under the mask.
    bool unmasked = false;
};

// What a `tex` instruction samples and where its operands are. The operand
// block is contiguous: coord[dims], then ref (shadow samplers: the depth to
// compare against), then lod (Explicit) or bias (ImplicitBias), then
// ddx[grad_dims] and ddy[grad_dims] (Implicit*: the screen derivatives of the
// coordinates that are filtered).
// Projection (texture2DProj, ...) is done by the frontend before the block.
// Rect: a rectangle texture, 2D with unnormalized coordinates.
// A1D, A2D: EXT_texture_array's 1D and 2D arrays; the coordinate's last
// component is the layer, which is not filtered and has no derivatives.
enum class TexTarget : uint8_t { T1D, T2D, T3D, Cube, Rect, A1D, A2D };  // glslrun::TextureTarget's order
enum class TexLod : uint8_t { Explicit, Implicit, ImplicitBias };
struct TexInfo {
    TexTarget target = TexTarget::T2D;
    bool shadow = false;
    TexLod lod = TexLod::Implicit;
    // The derivatives are the program's (texture*GradARB), not the screen's:
    // they are the lane's own, never shared by a quad.
    bool grad = false;

    // Coordinate components, an array's layer included.
    uint32_t dims() const {
        switch (target) {
        case TexTarget::T1D: return 1;
        case TexTarget::T2D:
        case TexTarget::Rect:
        case TexTarget::A1D: return 2;
        default: return 3;
        }
    }
    bool arrayed() const { return target == TexTarget::A1D || target == TexTarget::A2D; }
    // Components with derivatives: all but an array's layer.
    uint32_t grad_dims() const { return arrayed() ? dims() - 1 : dims(); }
    uint32_t ref_at() const { return dims(); }
    uint32_t lod_at() const { return dims() + (shadow ? 1 : 0); }
    uint32_t ddx_at() const { return lod_at() + (lod == TexLod::Implicit ? 0 : 1); }
    uint32_t ddy_at() const { return ddx_at() + grad_dims(); }
    uint32_t operand_count() const { return lod == TexLod::Explicit ? ddx_at() : ddy_at() + grad_dims(); }
    uint32_t encode() const {
        return uint32_t(target) | uint32_t(shadow) << 3 | uint32_t(lod) << 4 | uint32_t(grad) << 6;
    }
    static TexInfo decode(uint32_t bits) {
        return {TexTarget(bits & 7), bool(bits >> 3 & 1), TexLod(bits >> 4 & 3), bool(bits >> 6 & 1)};
    }
};
inline constexpr uint32_t kTexResults = 4;

// Where a node comes from: the line (and column, 0 when glslang gives none)
// in source `source` of its stage (an index into Shader::sources).
struct SourceLoc {
    int line = 0;
    uint16_t column = 0;
    uint16_t source = 0;
};

enum class NodeKind : uint8_t {
    Instr,     // `instr`
    If,        // if (cond) body else alt
    Loop,      // loop { body } continue { alt }: repeats while any lane is active
    Break,     // leaves the innermost Loop
    Continue,  // skips to the innermost Loop's continue block (alt)
    Return,    // leaves the innermost Call or Scope
    Discard,   // fragment only: kills the lane for the rest of the invocation
    Call,      // runs functions[callee].body; Return inside it ends the call
    Scope,     // body is an inlined function: Return inside it ends the scope
};

struct Node {
    NodeKind kind = NodeKind::Instr;
    Instr instr;
    Reg cond = kNoReg;       // If
    uint32_t callee = 0;     // Call
    std::vector<Node> body;  // If: then; Loop: body; Scope: body
    std::vector<Node> alt;   // If: else; Loop: continue block
    SourceLoc loc;
};
using Block = std::vector<Node>;

struct Function {
    std::string name;  // GLSL name, e.g. "shade"
    Block body;
};

// A shader interface variable (attribute, varying, built-in input/output):
// `count` consecutive registers starting at `first`, all of kind `kind`.
struct Binding {
    std::string name;  // GL name: "gl_Vertex", "normal", "gl_TexCoord[1]"
    Kind kind = Kind::F32;
    Reg first = kNoReg;
    uint32_t count = 0;
};

enum class Stage : uint8_t { Vertex, Fragment };

// A GLSL variable held in registers (debugging: trace, --find-nan): `count`
// registers from `first`, declared in `function` ("" for globals). Valid
// until ir/regalloc.cpp renumbers the registers, which clears the list.
struct Variable {
    std::string name;
    std::string function;
    std::string type;  // GLSL type: "vec3", "mat4", "float[4]"
    Reg first = kNoReg;
    uint32_t count = 0;
};

// Where a check_undef instruction came from (ir/undefined.h): its UndefOp
// and the source position of the call or operator it checks.
struct UndefSite {
    uint8_t op = 0;  // ir::UndefOp
    SourceLoc loc;
    uint32_t length = 0;  // UndefOp::Index: the array's length
};

struct Shader {
    Stage stage = Stage::Vertex;
    std::vector<Kind> regs;  // kind of every register; size = register count
    // Straight-line code that depends only on uniforms and constants
    // (ir/hoist.cpp): run once per draw, for all lanes, before any batch.
    Block prologue;
    Block body;              // global initializers, then main's body (in a Scope)
    std::vector<Function> functions;  // callees of Call nodes
    std::vector<Binding> inputs;      // filled by the caller before running
    std::vector<Binding> outputs;     // read by the caller after running
    bool uses_derivatives = false;
    bool uses_discard = false;
    // Whether a helper lane's texture lookups can change a fragment's result
    // (ir/helper_lookups.cpp; set by optimize()). Where they cannot, the
    // fragment stage lets its batches' helper lanes skip their lookups.
    bool helper_lookups_matter = true;
    std::vector<std::string> sources;   // names of the stage's sources (SourceLoc::source)
    std::vector<Variable> variables;    // until regalloc
    std::vector<UndefSite> undef_sites;  // check_undef's imm[1]; empty unless checking
};

// Base type of a uniform leaf (GL's glGetActiveUniform view).
struct ValueType {
    Kind kind = Kind::F32;
    uint8_t cols = 1;  // 1 for scalars and vectors
    uint8_t rows = 1;  // vector size; matrix column height
    bool is_sampler = false;  // stored as an i32 texture unit
    uint32_t components() const { return uint32_t(cols) * rows; }
};

// One uniform leaf, named as GL names it: "u", "lights[2].pos", "m".
// Arrays of basic types are one leaf with `array_size` elements (GL style).
// Values live in the program's uniform store at `slot`, column-major, one
// 32-bit word per component, elements back to back.
struct Uniform {
    std::string name;
    ValueType type;
    uint32_t array_size = 1;  // 1 for non-arrays
    bool is_array = false;
    uint32_t slot = 0;
    bool builtin = false;  // gl_* state, set by the GL state object
    bool read = true;      // some instruction reads it (mark_read_uniforms)
};

// How one fragment-shader input is fed from the vertex shader's outputs.
// `vs_output` names the source, an index into vertex.outputs (a varying is
// always a whole output). For gl_Color / gl_SecondaryColor the back
// colour source is given too; the rasterizer picks one by facing when
// two-sided colour is enabled.
struct VaryingLink {
    uint32_t fs_input = 0;  // index into fragment.inputs
    int vs_output = -1;     // -1: not written by the VS (value undefined: 0)
    int vs_back_output = -1;
    bool is_color = false;  // clamped to [0,1] as GL 2.1 does for colour varyings
};

struct Program {
    Shader vertex;
    Shader fragment;
    // The vertex stage is glslrun's stand-in for GL's fixed-function one (no
    // vertex shader was given): the rasterizer treats its gl_PointSize as
    // GL treats the fixed-function point size.
    bool fixed_function_vertex = false;
    std::vector<Uniform> uniforms;
    uint32_t uniform_words = 0;
    // Initial uniform values (GLSL 1.20 initializers), uniform_words words;
    // GL's default is 0 for everything else.
    std::vector<uint32_t> uniform_defaults;
    std::vector<VaryingLink> varyings;
};

// Uniform lookup by GL name: accepts "a", "a[0]", "a[3]", "s.f", "s[1].f".
// Returns nullptr if absent; *element receives the array element index.
const Uniform* find_uniform(const Program& p, const std::string& name, uint32_t* element);

}  // namespace glslrun::ir
