// One stage: variables, functions and calls, interface bindings.
#include <numeric>

#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include "frontend/lower.h"

namespace glslrun::frontend {

using ir::Kind;
using ir::Op;
using ir::Reg;

namespace {
constexpr int kGlobalKey = -1;
constexpr int kMainKey = 1 << 30;

std::vector<uint32_t> all_comps(uint32_t n) {
    std::vector<uint32_t> c(n);
    std::iota(c.begin(), c.end(), 0u);
    return c;
}

bool is_builtin_array_output(const std::string& name) { return name == "gl_TexCoord" || name == "gl_FragData"; }
}  // namespace

StageLowering::StageLowering(ir::Stage stage, UniformTable& uniforms, std::vector<Diagnostic>& diags, std::string file)
    : stage_(stage), uniforms_(uniforms), diags_(diags), file_(std::move(file)) {
    shader.stage = stage;
}

bool StageLowering::is_input(gl::TStorageQualifier q) const {
    if (q == gl::EvqVaryingIn) return true;
    return stage_ == ir::Stage::Fragment && (q == gl::EvqFragCoord || q == gl::EvqFace || q == gl::EvqPointCoord);
}

Access StageLowering::uniform_variable(const std::string& name, const gl::TType& type) {
    std::string err;
    const UniformTable::Var* v = uniforms_.declare(name, type, name.rfind("gl_", 0) == 0, &err);
    Access a;
    if (!v) {
        diags_.push_back(Diagnostic{file_, 0, err, false});
        std::vector<Kind> kinds;
        flatten_kinds(type, kinds);
        a.base = new_range(kinds);
        a.comps = all_comps(uint32_t(kinds.size()));
        return a;
    }
    a.uniform = true;
    a.base = v->slot;
    a.comps = all_comps(v->size);
    return a;
}

Access StageLowering::interface_variable(const std::string& name, const gl::TType& type, gl::TStorageQualifier storage) {
    auto it = interface.find(name);
    if (it == interface.end()) {
        InterfaceVar var;
        var.input = is_input(storage);
        var.signature = type_signature(type);
        if (is_builtin_array_output(name)) {
            // Sized by use (implicitly) in glslang; reserve the GL maximum so
            // every reference fits, bind only the elements the shader sizes.
            var.kinds.assign(8 * 4, Kind::F32);
            var.elements = array_length(type);
        } else {
            flatten_kinds(type, var.kinds);
        }
        var.base = new_range(var.kinds);
        it = interface.emplace(name, var).first;
    }
    InterfaceVar& var = it->second;
    if (var.elements) var.elements = std::max(var.elements, array_length(type));
    Access a;
    a.base = var.base;
    a.comps = all_comps(var.elements ? var.elements * 4 : uint32_t(var.kinds.size()));
    return a;
}

Access StageLowering::variable(gl::TIntermSymbol* sym) {
    std::string name = sym->getName().c_str();
    const gl::TType& type = sym->getType();
    gl::TStorageQualifier storage = type.getQualifier().storage;
    switch (storage) {
    case gl::EvqTemporary:
    case gl::EvqIn:
    case gl::EvqOut:
    case gl::EvqInOut:
    case gl::EvqConstReadOnly: {
        auto key = std::make_pair(cur_func_, sym->getId());
        auto it = locals_.find(key);
        if (it == locals_.end()) {
            std::vector<Kind> kinds;
            flatten_kinds(type, kinds);
            it = locals_.emplace(key, new_range(kinds)).first;
            name_variable(name, cur_info_ ? cur_info_->name : std::string(), type, it->second);
        }
        Access a;
        a.base = it->second;
        a.comps = all_comps(flat_size(type));
        return a;
    }
    case gl::EvqConst:
        if (sym->getConstArray().size() > 0) return materialize(constant(sym->getConstArray(), type));
        [[fallthrough]];
    case gl::EvqGlobal: {
        referenced.insert(name);
        auto it = globals_.find(name);
        if (it == globals_.end()) {
            std::vector<Kind> kinds;
            flatten_kinds(type, kinds);
            it = globals_.emplace(name, new_range(kinds)).first;
            name_variable(name, "", type, it->second);
        }
        Access a;
        a.base = it->second;
        a.comps = all_comps(flat_size(type));
        return a;
    }
    case gl::EvqUniform: referenced.insert(name); return uniform_variable(name, type);
    case gl::EvqVaryingIn:
    case gl::EvqVaryingOut:
    case gl::EvqPosition:
    case gl::EvqPointSize:
    case gl::EvqClipVertex:
    case gl::EvqFace:
    case gl::EvqFragCoord:
    case gl::EvqPointCoord:
    case gl::EvqFragColor:
    case gl::EvqFragDepth: referenced.insert(name); return interface_variable(name, type, storage);
    default: break;
    }
    fail(sym, fmt::format("'{}' : unsupported storage qualifier", name));
    return materialize(zeros(type));
}

void StageLowering::declare_linker_objects(gl::TIntermAggregate* objects) {
    for (TIntermNode* n : objects->getSequence()) {
        gl::TIntermSymbol* sym = n->getAsSymbolNode();
        if (!sym) continue;
        std::string name = sym->getName().c_str();
        const gl::TType& type = sym->getType();
        gl::TStorageQualifier q = type.getQualifier().storage;
        if (q == gl::EvqUniform) {
            uniform_variable(name, type);
            std::string err;
            if (sym->getConstArray().size() > 0)
                if (const UniformTable::Var* v = uniforms_.declare(name, type, false, &err))
                    uniforms_.set_default(*v, sym->getConstArray());
        } else if (name.rfind("gl_", 0) != 0 &&
                   ((stage_ == ir::Stage::Vertex && q == gl::EvqVaryingOut) ||
                    (stage_ == ir::Stage::Fragment && q == gl::EvqVaryingIn))) {
            declared_varyings[name] = type_signature(type);
        }
    }
}

// ----------------------------------------------------------- functions ---
void StageLowering::prepare_function(gl::TIntermAggregate* def) {
    std::string mangled = def->getName().c_str();
    FuncInfo f;
    f.name = mangled.substr(0, mangled.find('('));
    f.def = def;
    bool is_main = mangled == "main(";
    if (!is_main) {
        f.index = uint32_t(shader.functions.size());
        shader.functions.push_back(ir::Function{f.name, {}});
    }
    int key = is_main ? kMainKey : int(f.index);
    const gl::TIntermSequence& seq = def->getSequence();
    if (!seq.empty() && seq[0]->getAsAggregate()) {
        for (TIntermNode* p : seq[0]->getAsAggregate()->getSequence()) {
            gl::TIntermSymbol* sym = p->getAsSymbolNode();
            if (!sym) continue;
            std::vector<Kind> kinds;
            flatten_kinds(sym->getType(), kinds);
            FuncInfo::Param param;
            param.base = new_range(kinds);
            param.storage = sym->getType().getQualifier().storage;
            param.size = uint32_t(kinds.size());
            locals_[std::make_pair(key, sym->getId())] = param.base;
            name_variable(sym->getName().c_str(), f.name, sym->getType(), param.base);
            f.params.push_back(param);
        }
    }
    if (def->getType().getBasicType() != gl::EbtVoid) {
        std::vector<Kind> kinds;
        flatten_kinds(def->getType(), kinds);
        f.ret = new_range(kinds);
        f.ret_size = uint32_t(kinds.size());
    }
    funcs_[mangled] = f;
}

void StageLowering::lower_function(FuncInfo& f, ir::Block& into) {
    cur_func_ = f.name == "main" && f.def->getName() == "main(" ? kMainKey : int(f.index);
    cur_info_ = &f;
    cur_ = &into;
    const gl::TIntermSequence& seq = f.def->getSequence();
    if (seq.size() > 1) stmt(seq[1]);
    cur_info_ = nullptr;
}

// Arguments are evaluated in order into temporaries before any parameter is
// written (an argument may itself call the same function); out/inout
// parameters are copied back in order after the call.
Value StageLowering::call(gl::TIntermAggregate* node) {
    auto it = funcs_.find(node->getName().c_str());
    if (it == funcs_.end())
        return fail(node, fmt::format("'{}' : no function definition (body) found", node->getName().c_str()));
    FuncInfo& f = it->second;
    const gl::TIntermSequence& args = node->getSequence();
    if (args.size() != f.params.size()) return fail(node, "internal: argument count mismatch");
    std::vector<Value> ins(args.size());
    std::vector<Access> outs(args.size());
    for (size_t i = 0; i < args.size(); ++i) {
        gl::TIntermTyped* arg = args[i]->getAsTyped();
        gl::TStorageQualifier q = f.params[i].storage;
        if (gl::TIntermSymbol* sym = arg->getAsSymbolNode()) {
            auto wb = writeback_targets_.find(sym->getId());
            if (wb != writeback_targets_.end()) {
                prebound_places_[wb->second] = access(wb->second);
                writeback_targets_.erase(wb);
            }
        }
        if (q == gl::EvqOut || q == gl::EvqInOut) outs[i] = access(arg);
        if (q == gl::EvqInOut) ins[i] = read(outs[i]);
        if (q != gl::EvqOut && q != gl::EvqInOut) ins[i] = expr(arg);
    }
    set_line(node);
    for (size_t i = 0; i < args.size(); ++i) {
        if (ins[i].regs.empty()) continue;
        if (ins[i].regs.size() != f.params[i].size) return fail(node, "internal: argument size mismatch");
        for (uint32_t c = 0; c < f.params[i].size; ++c)
            mov_to(f.params[i].base + c, convert(Value{{ins[i].regs[c]}}, kind(f.params[i].base + c)).regs[0]);
    }
    ir::Node n;
    n.kind = ir::NodeKind::Call;
    n.callee = f.index;
    emit_node(std::move(n));
    for (size_t i = 0; i < args.size(); ++i) {
        if (outs[i].comps.empty()) continue;
        Value v;
        for (uint32_t c = 0; c < f.params[i].size; ++c) v.regs.push_back(mov(f.params[i].base + c));
        write(outs[i], v, node);
    }
    Value ret;
    for (uint32_t c = 0; c < f.ret_size; ++c) ret.regs.push_back(mov(f.ret + c));
    return ret;
}

namespace {
// The temporary behind a converted out argument, under the conversion
// (unary convert or one-argument constructor) of a write-back's right side.
gl::TIntermSymbol* temp_arg_of(gl::TIntermTyped* rhs) {
    while (rhs) {
        if (gl::TIntermSymbol* sym = rhs->getAsSymbolNode())
            return sym->getName().compare(0, 7, "tempArg") == 0 ? sym : nullptr;
        if (gl::TIntermUnary* u = rhs->getAsUnaryNode()) {
            rhs = u->getOperand();
            continue;
        }
        gl::TIntermAggregate* agg = rhs->getAsAggregate();
        if (!agg || agg->getSequence().size() != 1) return nullptr;
        rhs = agg->getSequence()[0]->getAsTyped();
    }
    return nullptr;
}

bool is_call(TIntermNode* n) {
    if (gl::TIntermBinary* b = n->getAsBinaryNode(); b && b->getOp() == gl::EOpAssign) n = b->getRight();
    gl::TIntermAggregate* agg = n->getAsAggregate();
    return agg && agg->getOp() == gl::EOpFunctionCall;
}
}  // namespace

// glslang lowers `f(..., lvalue, ...)` with a converted out parameter to
// `(f(..., tempArg, ...), lvalue = convert(tempArg))`, which would evaluate
// the l-value (and its dynamic indices) after the call. GLSL evaluates it
// with the arguments, so call() computes its place when it reaches tempArg.
void StageLowering::note_out_conversions(gl::TIntermAggregate* comma) {
    const gl::TIntermSequence& seq = comma->getSequence();
    if (seq.empty() || !is_call(seq[0])) return;
    for (size_t i = 1; i < seq.size(); ++i) {
        gl::TIntermBinary* b = seq[i]->getAsBinaryNode();
        if (!b || b->getOp() != gl::EOpAssign) continue;
        if (gl::TIntermSymbol* tmp = temp_arg_of(b->getRight())) writeback_targets_[tmp->getId()] = b->getLeft();
    }
}

Value StageLowering::ftransform() {
    gl::TType mat(gl::EbtFloat, gl::EvqUniform, 0, 4, 4);
    gl::TType vec(gl::EbtFloat, gl::EvqVaryingIn, 4);
    Value m = read(uniform_variable("gl_ModelViewProjectionMatrix", mat));
    Value v = read(interface_variable("gl_Vertex", vec, gl::EvqVaryingIn));
    return matrix_times_vector(m, 4, 4, v);
}

// ------------------------------------------------------------ the stage ---
void StageLowering::run(gl::TIntermediate* im) {
    gl::TIntermAggregate* root = im->getTreeRoot() ? im->getTreeRoot()->getAsAggregate() : nullptr;
    if (!root) {
        fail(nullptr, "internal: empty syntax tree");
        return;
    }
    std::vector<TIntermNode*> inits;
    FuncInfo* main_info = nullptr;
    for (TIntermNode* child : root->getSequence()) {
        gl::TIntermAggregate* agg = child->getAsAggregate();
        if (agg && agg->getOp() == gl::EOpLinkerObjects) declare_linker_objects(agg);
        else if (agg && agg->getOp() == gl::EOpFunction) prepare_function(agg);
        else inits.push_back(child);
    }
    if (auto it = funcs_.find("main("); it != funcs_.end()) main_info = &it->second;
    if (!main_info) {
        fail(nullptr, "Missing entry point: Each stage requires one entry point");
        return;
    }

    // Global initializers in order, then main's body in a Scope.
    ir::Block body;
    cur_ = &body;
    cur_func_ = kGlobalKey;
    for (TIntermNode* n : inits) stmt(n);
    ir::Node scope;
    scope.kind = ir::NodeKind::Scope;
    lower_function(*main_info, scope.body);
    cur_ = &body;
    scope.loc.line = main_info->def->getLoc().line;
    body.push_back(std::move(scope));

    for (auto& [mangled, f] : funcs_) {
        if (&f == main_info) continue;
        ir::Block fb;
        lower_function(f, fb);
        shader.functions[f.index].body = std::move(fb);
    }

    finish_bindings();
    // Unwritten outputs must read as 0.
    ir::Block prefix;
    cur_ = &prefix;
    line_ = 0;
    loc_ = {};
    for (const ir::Binding& b : shader.outputs)
        for (uint32_t i = 0; i < b.count; ++i) {
            ir::Instr in;
            in.op = Op::konst;
            in.type = b.kind;
            in.dst = b.first + i;
            emit(in);
        }
    prefix.insert(prefix.end(), std::make_move_iterator(body.begin()), std::make_move_iterator(body.end()));
    shader.body = std::move(prefix);
    cur_ = nullptr;
}

void StageLowering::finish_bindings() {
    if (stage_ == ir::Stage::Vertex && !interface.count("gl_Position"))
        interface_variable("gl_Position", gl::TType(gl::EbtFloat, gl::EvqPosition, 4), gl::EvqPosition);
    for (const auto& [name, var] : interface) {
        std::vector<ir::Binding>& list = var.input ? shader.inputs : shader.outputs;
        if (var.elements) {
            for (uint32_t i = 0; i < var.elements; ++i)
                list.push_back(ir::Binding{fmt::format("{}[{}]", name, i), Kind::F32, var.base + 4 * i, 4});
        } else {
            list.push_back(ir::Binding{name, var.kinds[0], var.base, uint32_t(var.kinds.size())});
        }
    }
}

}  // namespace glslrun::frontend
