// Clip-space clipping (GL 2.1 §2.12): the near and far planes, user clip
// planes (distances computed from gl_ClipVertex by the caller), and x/y only
// against a wide guard band, so that window coordinates stay in the range of
// the fixed-point rasterizer. Clipping interpolates every attribute linearly
// in clip space, which keeps perspective-correct interpolation exact.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace glslrun::raster {

inline constexpr int kMaxUserPlanes = 6;

struct ClipVertex {
    glm::vec4 pos{0.0f};                       // clip coordinates
    std::array<float, kMaxUserPlanes> user{};  // signed distances to the user planes
    const float* attrs = nullptr;              // `attr_count` floats, owned elsewhere
};

struct ClipParams {
    float guard = 1.0f;          // |x|, |y| <= guard * w
    uint32_t user_planes = 0;    // enabled user planes (bit i)
    uint32_t attr_count = 0;
};

// Storage for the attributes of vertices that clipping creates; pointers stay
// valid until clear().
class AttrArena {
public:
    float* alloc(size_t n) {
        blocks_.emplace_back(n);
        return blocks_.back().data();
    }
    void clear() { blocks_.clear(); }
private:
    std::vector<std::vector<float>> blocks_;
};

// Bit p set: the vertex is outside plane p (0 near, 1 far, 2..5 guard band,
// 6.. user planes).
uint32_t outcode(const ClipVertex& v, const ClipParams& params);

// Clips a convex polygon in place; it may come back with fewer than 3 vertices.
void clip_polygon(std::vector<ClipVertex>& poly, const ClipParams& params, AttrArena& arena);
// Clips a segment in place; false when nothing is left.
bool clip_segment(ClipVertex& a, ClipVertex& b, const ClipParams& params, AttrArena& arena);

}  // namespace glslrun::raster
