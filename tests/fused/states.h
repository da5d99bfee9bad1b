// Fused pipeline states the unit tests start from.
#pragma once
#include "raster/fused/state.h"

namespace fused_test {

// A state the generated code has always taken: a varying and gl_FrontFacing,
// gl_FragColor, an early depth test.
inline glslrun::raster::fused::State plain_state(bool avx2) {
    using namespace glslrun;
    raster::fused::State s;
    s.inputs = {{raster::fused::InputSource::Varying, 0, ir::Kind::F32, false},
                {raster::fused::InputSource::FrontFacing, 0, ir::Kind::Bool, false}};
    s.color_channels = 4;
    s.ops.depth_test = true;
    s.early_depth = true;
    s.avx2 = avx2;
    return s;
}

}  // namespace fused_test
