// fused::fusable() takes only the states the generated code knows (opt-in),
// and fused::state_key() tells states apart (raster/fused/state.h).
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "raster/fused/state.h"
#include "tests/fused/states.h"

using namespace glslrun;
using namespace glslrun::raster;

namespace {

// A State with a field that nobody taught the generated code, as a new GL
// state would be.
struct FutureState : fused::State {
    int new_operation = 0;
    bool operator==(const FutureState&) const = default;
};

struct Change {
    const char* name;
    std::function<void(fused::State&)> apply;
};

// Changes of a state that the generated code does not implement (yet).
const std::vector<Change>& refused_changes() {
    static const std::vector<Change> changes = {
        {"the shader debugger", [](fused::State& s) { s.probe = true; }},
        {"an int input", [](fused::State& s) { s.inputs[0].kind = ir::Kind::I32; }},
        {"a non-float output", [](fused::State& s) { s.float_outputs = false; }},
        {"half-float storage", [](fused::State& s) { s.ops.float_color = true, s.ops.half_float = true; }},
    };
    return changes;
}

// Changes that it does implement.
const std::vector<Change>& generated_changes() {
    static const std::vector<Change> changes = {
        {"the alpha test", [](fused::State& s) { s.ops.alpha_test = true, s.ops.alpha_func = CompareFunc::Less; }},
        {"two draw buffers", [](fused::State& s) { s.ops.draw_buffers = 2, s.more_channels[1] = 4; }},
        {"the stencil test", [](fused::State& s) { s.ops.stencil_test = true, s.ops.stencil[1].fail = StencilOp::Zero; }},
        {"GL_COORD_REPLACE", [](fused::State& s) { s.inputs[0].sprite_coord = true, s.inputs[0].component = 1; }},
        {"a logic op", [](fused::State& s) { s.ops.logic_op = true, s.ops.logic = LogicOp::Xor; }},
        {"blending, late depth", [](fused::State& s) { s.ops.blend = true, s.early_depth = false; }},
        {"a colour mask, late depth", [](fused::State& s) { s.ops.color_mask[1] = false, s.early_depth = false; }},
        {"blending into floats", [](fused::State& s) { s.ops.blend = true, s.ops.float_color = true; }},
        {"a colour mask into floats", [](fused::State& s) { s.ops.color_mask[0] = false, s.ops.float_color = true; }},
    };
    return changes;
}

}  // namespace

TEST_CASE("fusable takes the states the generated code knows", "[fused]") {
    fused::State s = fused_test::plain_state(true);
    CHECK(fused::fusable(s));
    s.ops.blend = true;
    s.ops.blend_state.src_rgb = BlendFactor::SrcAlpha;
    s.ops.color_mask = {true, false, true, true};
    s.ops.rounding = ColorRounding::Gpu;
    CHECK(fused::fusable(s));
    s.ops.float_color = true;
    CHECK(fused::fusable(s));
    // A disabled test's settings do not matter.
    fused::State off = fused_test::plain_state(true);
    off.ops.alpha_func = CompareFunc::Never;
    off.ops.stencil[1].func = CompareFunc::Equal;
    off.ops.logic = LogicOp::Xor;
    CHECK(fused::fusable(off));
}

TEST_CASE("fusable takes each state the generated code implements", "[fused]") {
    for (const Change& change : generated_changes()) {
        fused::State s = fused_test::plain_state(true);
        change.apply(s);
        INFO(change.name);
        CHECK(fused::fusable(s));
    }
}

TEST_CASE("fusable refuses each state the generated code does not implement", "[fused]") {
    for (const Change& change : refused_changes()) {
        fused::State s = fused_test::plain_state(true);
        change.apply(s);
        INFO(change.name);
        CHECK_FALSE(fused::fusable(s));
    }
}

TEST_CASE("fusable refuses a state field that nobody taught it", "[fused]") {
    // The rule resets what it knows and compares the rest with a default
    // state: a new field set away from its default is left over.
    FutureState s;
    static_cast<fused::State&>(s) = fused_test::plain_state(true);
    CHECK(fused::only_known_fields(s));
    s.new_operation = 1;
    CHECK_FALSE(fused::only_known_fields(s));
}

TEST_CASE("state_key tells states apart and keeps equal ones together", "[fused]") {
    const fused::State base = fused_test::plain_state(true);
    CHECK(fused::state_key(base) == fused::state_key(fused_test::plain_state(true)));
    // NaN's bits: a state's key is its own.
    fused::State nan = base;
    nan.ops.alpha_test = true;
    nan.ops.alpha_ref = std::nanf("");
    CHECK(fused::state_key(nan) == fused::state_key(fused::State(nan)));
    std::vector<Change> changes = refused_changes();
    changes.insert(changes.end(), generated_changes().begin(), generated_changes().end());
    changes.push_back({"depth func", [](fused::State& s) { s.ops.depth_func = CompareFunc::Gequal; }});
    changes.push_back({"depth write", [](fused::State& s) { s.ops.depth_write = false; }});
    changes.push_back({"rounding", [](fused::State& s) { s.ops.rounding = ColorRounding::Gpu; }});
    changes.push_back({"blend factor", [](fused::State& s) { s.ops.blend = true, s.ops.blend_state.dst_alpha = BlendFactor::DstColor; }});
    changes.push_back({"blend colour", [](fused::State& s) { s.ops.blend = true, s.ops.blend_state.color.b = 0.5f; }});
    changes.push_back({"alpha ref", [](fused::State& s) { s.ops.alpha_test = true, s.ops.alpha_ref = 0.25f; }});
    changes.push_back({"stencil op", [](fused::State& s) { s.ops.stencil_test = true, s.ops.stencil[1].depth_fail = StencilOp::Incr; }});
    changes.push_back({"stencil ref", [](fused::State& s) { s.ops.stencil_test = true, s.ops.stencil[0].ref = 3; }});
    changes.push_back({"logic", [](fused::State& s) { s.ops.logic_op = true, s.ops.logic = LogicOp::Nand; }});
    changes.push_back({"colour mask", [](fused::State& s) { s.ops.color_mask[3] = false; }});
    changes.push_back({"input index", [](fused::State& s) { s.inputs[0].index = 5; }});
    changes.push_back({"input source", [](fused::State& s) { s.inputs[0].source = fused::InputSource::FragCoord; }});
    changes.push_back({"inputs", [](fused::State& s) { s.inputs.pop_back(); }});
    changes.push_back({"channels", [](fused::State& s) { s.color_channels = 3; }});
    changes.push_back({"depth output", [](fused::State& s) { s.depth_output = true; }});
    changes.push_back({"ISA", [](fused::State& s) { s.avx2 = false; }});
    for (const Change& change : changes) {
        fused::State s = base;
        change.apply(s);
        INFO(change.name);
        CHECK_FALSE(s == base);
        CHECK(fused::state_key(s) != fused::state_key(base));
    }
    // Settings of a disabled operation draw nothing different: one key.
    fused::State off = base;
    off.ops.blend_state.src_rgb = BlendFactor::Zero;
    off.ops.stencil[0].ref = 9;
    CHECK(fused::state_key(off) == fused::state_key(base));
}
