// Mipmap generation as NVIDIA's OpenGL driver does it, for Precision::Fast
// (ColorRounding::Gpu): see mipmap_gpu.cpp.
#pragma once
#include "glslrun/glslrun.h"

namespace glslrun::rt {

// Levels base+1 .. q of every face of `texture` as NVIDIA's glGenerateMipmap
// makes them from level_base. It applies to RGBA8 1D, 2D and cube textures
// whose every level halves both sides exactly (even sizes down to 1, the
// measured case); for any other texture it returns false and changes nothing.
bool generate_gpu_mipmaps(Texture& texture);

}  // namespace glslrun::rt
