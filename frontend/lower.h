// Internal to frontend/: lowering of one linked glslang stage into an
// ir::Shader. Values are scalarized (a Value is one register per component);
// variables are contiguous register ranges (or uniform slot ranges) with
// arrays and structs flattened and matrices column-major.
#pragma once
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glslang/Include/intermediate.h>

#include "glslrun/glslrun.h"
#include "ir/ir.h"
#include "ir/undefined.h"

namespace glslrun::frontend {

namespace gl = glslang;

// ------------------------------------------------------------ types.cpp ---
ir::Kind kind_of(const gl::TType& t);
uint32_t array_length(const gl::TType& t);  // implicit size for unsized arrays
gl::TType element_type(const gl::TType& t);  // array element (outer dimension)
uint32_t flat_size(const gl::TType& t);
// The same, in 64 bits (saturating at 2^40): for checking sizes before flat_size's uint32.
uint64_t components_of(const gl::TType& t);
void flatten_kinds(const gl::TType& t, std::vector<ir::Kind>& out);
uint32_t member_offset(const gl::TType& struct_type, int member);
std::string type_signature(const gl::TType& t);  // "vec3", "float[4]", "struct S{float a;}"
ir::ValueType value_type(const gl::TType& t);     // of a non-array, non-struct type
uint32_t float_bits(float f);

// The program-wide uniform store layout, shared by both stages so that a
// uniform declared in both gets one slot range.
struct UniformTable {
    struct Var {
        uint32_t slot = 0;
        uint32_t size = 0;
        std::string signature;
    };
    std::map<std::string, Var> vars;
    std::vector<ir::Uniform> leaves;
    std::vector<ir::Kind> slot_kinds;
    std::vector<uint32_t> defaults;  // GLSL 1.20 initializers, one word per slot (0 when none)
    // Adds the variable on first sight. Returns nullptr and sets *error if a
    // variable of that name was declared with another type.
    const Var* declare(const std::string& name, const gl::TType& type, bool builtin, std::string* error);
    void set_default(const Var& var, const gl::TConstUnionArray& values);
};

struct Value {
    std::vector<ir::Reg> regs;
};

// A place in a variable: registers or uniform slots base + comps[i]
// (+ clamp(index, 0, count-1) * stride when `index` is set).
struct Access {
    bool uniform = false;
    uint32_t base = 0;
    ir::Reg index = ir::kNoReg;
    uint32_t count = 0, stride = 0;
    std::vector<uint32_t> comps;
};

// A shader interface variable (attribute, varying, built-in input/output).
struct InterfaceVar {
    ir::Reg base = ir::kNoReg;
    std::vector<ir::Kind> kinds;
    bool input = false;
    uint32_t elements = 0;  // > 0: one binding per element ("gl_TexCoord[i]")
    std::string signature;
};

struct FuncInfo {
    struct Param {
        ir::Reg base = ir::kNoReg;
        gl::TStorageQualifier storage = gl::EvqIn;
        uint32_t size = 0;
    };
    std::string name;
    uint32_t index = 0;  // into shader.functions
    gl::TIntermAggregate* def = nullptr;
    std::vector<Param> params;
    ir::Reg ret = ir::kNoReg;
    uint32_t ret_size = 0;
};

class StageLowering {
public:
    StageLowering(ir::Stage stage, UniformTable& uniforms, std::vector<Diagnostic>& diags, std::string file);
    void run(gl::TIntermediate* im);

    ir::Shader shader;
    std::map<std::string, InterfaceVar> interface;        // referenced in code, by GLSL name
    std::map<std::string, std::string> declared_varyings;  // user varyings declared: name -> signature
    std::set<std::string> referenced;                       // every global name used in code
    // CompileOptions::check_undefined: a check_undef before every built-in
    // call and operator that GLSL leaves undefined for some operands.
    bool check_undefined = false;

private:
    // --- lower_shader.cpp: variables, functions, bindings
    void declare_linker_objects(gl::TIntermAggregate* objects);
    void prepare_function(gl::TIntermAggregate* def);
    void lower_function(FuncInfo& f, ir::Block& into);
    Access variable(gl::TIntermSymbol* sym);
    Access interface_variable(const std::string& name, const gl::TType& type, gl::TStorageQualifier storage);
    Access uniform_variable(const std::string& name, const gl::TType& type);
    void finish_bindings();
    bool is_input(gl::TStorageQualifier q) const;
    Value call(gl::TIntermAggregate* node);
    void note_out_conversions(gl::TIntermAggregate* comma);
    Value ftransform();

    // --- lower_expr.cpp
    Value expr(gl::TIntermTyped* n);
    Value binary(gl::TIntermBinary* n);
    Value unary(gl::TIntermUnary* n);
    Value aggregate(gl::TIntermAggregate* n);
    Value ternary(gl::TIntermSelection* n);
    Value logical(gl::TIntermBinary* n);
    Value assign(gl::TIntermBinary* n);
    Value arith(gl::TOperator op, const gl::TType& lt, const Value& a, const gl::TType& rt, const Value& b,
                const gl::TType& result);
    Value compare_all(bool equal, const Value& a, const Value& b);
    Value construct(gl::TIntermAggregate* n);
    Value constant(const gl::TConstUnionArray& values, const gl::TType& type);
    Value convert(const Value& v, ir::Kind to);
    Value increment(gl::TIntermUnary* n);

    // --- lower_access.cpp
    Access access(gl::TIntermTyped* n);
    Access materialize(const Value& v);
    void index_constant(Access& a, uint32_t offset);
    void index_dynamic(Access& a, ir::Reg idx, uint32_t count, uint32_t stride);
    ir::Kind access_kind(const Access& a, size_t i) const;
    Value read(const Access& a);
    void write(const Access& a, const Value& v, TIntermNode* where);

    // --- lower_builtins.cpp
    Value builtin_unary(gl::TIntermUnary* n, const Value& a);
    Value builtin_aggregate(gl::TIntermAggregate* n, const std::vector<Value>& args);
    Value componentwise(ir::Op op, const Value& a, const Value& b);
    Value componentwise3(ir::Op op1, ir::Op op2, const Value& a, const Value& b, const Value& c);
    ir::Reg dot(const Value& a, const Value& b);
    Value matrix_times_vector(const Value& m, int cols, int rows, const Value& v);
    Value vector_times_matrix(const Value& v, const Value& m, int cols, int rows);
    Value matrix_times_matrix(const Value& a, int acols, int arows, const Value& b, int bcols);

    // --- lower_checks.cpp: check_undef instructions (ir/undefined.h), when check_undefined is set
    void check_op(ir::UndefOp op, const std::vector<Value>& operands, uint32_t length = 0);
    void check_arith(gl::TOperator op, const Value& a, const Value& b);
    void check_builtin(gl::TOperator op, const std::vector<Value>& args);
    void check_index(ir::Reg index, uint32_t length);

    // --- lower_texture.cpp
    Value texture(gl::TIntermAggregate* n);

    // --- lower_stmt.cpp
    void stmt(TIntermNode* n);
    void loop(gl::TIntermLoop* n);
    void branch(gl::TIntermBranch* n);
    void selection(gl::TIntermSelection* n);
    ir::Reg condition(gl::TIntermTyped* n);

    // --- emission helpers (lower_stmt.cpp)
    ir::Reg new_reg(ir::Kind k);
    ir::Reg new_range(const std::vector<ir::Kind>& kinds);
    ir::Kind kind(ir::Reg r) const { return shader.regs[r]; }
    void emit(const ir::Instr& in);
    void emit_node(ir::Node n);
    ir::Reg alu(ir::Op op, ir::Kind result, ir::Reg a, ir::Reg b = ir::kNoReg, ir::Reg c = ir::kNoReg);
    ir::Reg mov(ir::Reg src);
    void mov_to(ir::Reg dst, ir::Reg src);
    ir::Reg konst_f(float f);
    ir::Reg konst_i(int32_t i);
    ir::Reg konst_b(bool b);
    ir::Reg konst_zero(ir::Kind k);
    Value zeros(const gl::TType& t);
    void emit_if(ir::Reg cond, ir::Block then_block, ir::Block else_block);
    template <class F>
    ir::Block build(F&& f) {
        ir::Block b;
        ir::Block* saved = cur_;
        cur_ = &b;
        f();
        cur_ = saved;
        return b;
    }
    Value fail(TIntermNode* n, const std::string& message, const gl::TType* type = nullptr);
    void set_line(TIntermNode* n);
    void name_variable(const std::string& name, const std::string& function, const gl::TType& type, ir::Reg first);

    ir::Stage stage_;
    UniformTable& uniforms_;
    std::vector<Diagnostic>& diags_;
    std::string file_;
    ir::Block* cur_ = nullptr;
    int line_ = 0;
    ir::SourceLoc loc_;  // of the node being lowered: line_ with its column and source
    int cur_func_ = -1;  // key of the function being lowered (locals are per function)
    FuncInfo* cur_info_ = nullptr;
    std::map<std::string, FuncInfo> funcs_;                    // by mangled name
    std::map<std::string, ir::Reg> globals_;                   // register globals by name
    std::map<std::pair<int, long long>, ir::Reg> locals_;      // (function, symbol id)
    // Out arguments that need a conversion: glslang writes them back after
    // the call through the original l-value node; that l-value must be
    // evaluated in argument order, before the call (see note_out_conversions).
    std::map<long long, gl::TIntermTyped*> writeback_targets_;  // tempArg symbol id -> l-value
    std::map<TIntermNode*, Access> prebound_places_;            // l-value -> place computed early
};

}  // namespace glslrun::frontend
