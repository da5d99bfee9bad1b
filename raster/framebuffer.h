// Colour and depth writes, shared by the fragment stage and the tests.
#pragma once
#include "glslrun/glslrun.h"

namespace glslrun::raster {

// RGBA8 storage: clamp to [0,1] and round to the nearest n/255 (NaN -> 0).
float quantize_unorm8(float v);
void write_color(Framebuffer& fb, int x, int y, glm::vec4 c);
bool depth_passes(GLState::DepthFunc func, float incoming, float stored);

}  // namespace glslrun::raster
