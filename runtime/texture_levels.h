// Mipmap arithmetic shared by texture objects (completeness, mipmap
// generation: texture.cpp) and sampling (level selection: sampling.cpp),
// so both read GL 2.1 §3.8.8's p and q the same way.
#pragma once
#include <algorithm>
#include <bit>
#include <cstddef>

#include "glslrun/glslrun.h"

namespace glslrun::rt {

// NEAREST and LINEAR read level_base alone; the other four need a mipmap (§3.8.10).
inline bool is_mipmap_filter(TextureFilter f) { return f != TextureFilter::Nearest && f != TextureFilter::Linear; }

// How many of (s, t, r) address the images: a cube face is a 2D image, an
// array's layer (t of a 1D array, r of a 2D array) is not filtered.
inline int texture_dims(TextureTarget target) {
    switch (target) {
    case TextureTarget::Tex1D:
    case TextureTarget::Tex1DArray: return 1;
    case TextureTarget::Tex3D: return 3;
    default: return 2;
    }
}

// A level that glTexImage never specified is stored as a default image (width 0).
inline bool defined(const TextureImage& image) { return image.width > 0; }

// The size of the next level in one dimension: max(1, floor(size / 2)) (§3.8.10).
inline int half_size(int size) { return std::max(1, size / 2); }

// floor(log2(maxsize)): the levels that follow `image` down to 1x1x1. Only
// the first `dims` sizes count: an array's layers stay at every level.
inline int levels_below(const TextureImage& image, int dims = 3) {
    const int size = std::max({image.width, dims > 1 ? image.height : 1, dims > 2 ? image.depth : 1, 1});
    return int(std::bit_width(unsigned(size))) - 1;
}

// q of §3.8.8: the last level mipmapping reads, min(p, level_max) with
// p = floor(log2(maxsize of level_base)) + level_base.
inline int last_mip_level(const TextureImage& base, const SamplerState& s, int dims = 3) {
    return std::min(levels_below(base, dims) + s.base_level, s.max_level);
}

// The image of `face` at `level`, or null where that level is not defined.
inline const TextureImage* level_image(const Texture& t, int face, int level) {
    if (face < 0 || face >= t.faces()) return nullptr;
    const std::vector<TextureImage>& levels = t.levels(face);
    if (level < 0 || size_t(level) >= levels.size() || !defined(levels[size_t(level)])) return nullptr;
    return &levels[size_t(level)];
}

}  // namespace glslrun::rt
