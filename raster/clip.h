// Clip-space clipping (GL 2.1 §2.12): the near and far planes, user clip
// planes (distances computed from gl_ClipVertex by the caller), and x/y only
// against a wide guard band, so that window coordinates stay in the range of
// the fixed-point rasterizer. Clipping interpolates every attribute linearly
// in clip space, which keeps perspective-correct interpolation exact.
#pragma once
#include <array>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

namespace glslrun::raster {

inline constexpr int kMaxUserPlanes = 6;
inline constexpr int kFrustumPlanes = 6;
// Each plane adds at most one vertex to a convex polygon.
inline constexpr int kMaxClipVertices = 3 + kFrustumPlanes + kMaxUserPlanes;

struct ClipVertex {
    glm::vec4 pos{0.0f};                       // clip coordinates
    std::array<float, kMaxUserPlanes> user{};  // signed distances to the user planes
    const float* attrs = nullptr;              // `attr_count` floats, owned elsewhere
    int source = -1;                           // the vertex of the arrays; -1: made by clipping
    // GL's edge flag: glPolygonMode(GL_LINE) draws the edge from this vertex
    // to the next, GL_POINT this vertex. Clipping keeps it on the parts of
    // the polygon's edges and sets it on edges along a user plane, not on
    // those along the view volume (Mesa's rule, after NVIDIA's).
    bool edge = true;
};

struct ClipParams {
    float guard = 1.0f;          // |x|, |y| <= guard * w
    uint32_t user_planes = 0;    // enabled user planes (bit i)
    uint32_t attr_count = 0;
};

// A convex polygon in fixed storage, so that clipping never allocates.
class ClipPolygon {
public:
    ClipPolygon() = default;
    ClipPolygon(std::initializer_list<ClipVertex> vs) {
        for (const ClipVertex& v : vs) push_back(v);
    }
    // Rounding can make a clipped polygon very slightly non-convex, so that a
    // plane adds more than one vertex; extra vertices are then dropped rather
    // than written out of bounds.
    void push_back(const ClipVertex& v) {
        if (size_ < v_.size()) v_[size_++] = v;
    }
    void clear() { size_ = 0; }
    size_t size() const { return size_; }
    ClipVertex& operator[](size_t i) { return v_[i]; }
    const ClipVertex& operator[](size_t i) const { return v_[i]; }
    const ClipVertex* begin() const { return v_.data(); }
    const ClipVertex* end() const { return v_.data() + size_; }
private:
    std::array<ClipVertex, kMaxClipVertices> v_;
    size_t size_ = 0;
};

// Storage for attribute vectors (clipped vertices, primitives of a draw):
// pointers stay valid until clear(), which keeps the memory for reuse. Memory
// comes in large blocks, so a draw allocates a few times, not per vertex.
class AttrArena {
public:
    float* alloc(size_t n);
    void clear() { block_ = 0, used_ = 0; }
private:
    static constexpr size_t kBlockFloats = size_t(1) << 16;
    struct Block { std::unique_ptr<float[]> data; size_t size = 0; };
    std::vector<Block> blocks_;
    size_t block_ = 0, used_ = 0;  // the block being filled and its fill level
};

// Bit p set: the vertex is outside plane p (0 near, 1 far, 2..5 guard band,
// 6.. user planes).
uint32_t outcode(const ClipVertex& v, const ClipParams& params);

// Clips a convex polygon in place; it may come back with fewer than 3 vertices.
void clip_polygon(ClipPolygon& poly, const ClipParams& params, AttrArena& arena);
// Clips a segment in place; false when nothing is left.
bool clip_segment(ClipVertex& a, ClipVertex& b, const ClipParams& params, AttrArena& arena);

}  // namespace glslrun::raster
