// The fused pipeline's logic op, blending and colour mask (FragmentState's) as generated
// vector code: raster::blend_unorm8's 8-bit steps (factor8, combine8 and
// mul_unorm8 in raster/fragment_ops.cpp), four lanes at a time.
#pragma once
#include <array>

#include <llvm/IR/IRBuilder.h>

#include "raster/fragment_ops.h"

namespace glslrun::raster::fused {

// The channels to store (i32 vectors of four lanes, 0 to 255 each) from the
// fragments' bytes `src` and the buffer's `dst`, channel by channel (RGBA):
// combined by the logic op where `ops` has one, else blended where it
// blends, then the colour mask; ColorRounding::Gpu as
// blend_unorm8 rounds with it (combine8_gpu's exact products).
std::array<llvm::Value*, 4> emit_blend_and_mask(llvm::IRBuilder<>& builder, const FragmentState& ops,
                                                const std::array<llvm::Value*, 4>& src,
                                                const std::array<llvm::Value*, 4>& dst);

}  // namespace glslrun::raster::fused
