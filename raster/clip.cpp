#include "raster/clip.h"

#include <algorithm>

namespace glslrun::raster {

float* AttrArena::alloc(size_t n) {
    while (block_ < blocks_.size() && used_ + n > blocks_[block_].size) ++block_, used_ = 0;
    if (block_ == blocks_.size()) {
        size_t size = std::max(n, kBlockFloats);
        blocks_.push_back({std::make_unique<float[]>(size), size});
        used_ = 0;
    }
    float* p = blocks_[block_].data.get() + used_;
    used_ += n;
    return p;
}

namespace {

float plane_distance(const ClipVertex& v, int plane, float guard) {
    const glm::vec4& p = v.pos;
    switch (plane) {
    case 0: return p.z + p.w;
    case 1: return p.w - p.z;
    case 2: return guard * p.w - p.x;
    case 3: return guard * p.w + p.x;
    case 4: return guard * p.w - p.y;
    case 5: return guard * p.w + p.y;
    default: return v.user[plane - kFrustumPlanes];
    }
}

bool plane_active(int plane, const ClipParams& params) {
    return plane < kFrustumPlanes || (params.user_planes >> (plane - kFrustumPlanes)) & 1u;
}

// The point at t along in -> out. Always interpolating from the inside vertex
// makes the shared edge of two triangles clip to bit-identical points.
ClipVertex lerp_vertex(const ClipVertex& in, const ClipVertex& out, float t, const ClipParams& params,
                       AttrArena& arena) {
    ClipVertex r;
    r.pos = in.pos + (out.pos - in.pos) * t;
    for (int i = 0; i < kMaxUserPlanes; ++i) r.user[i] = in.user[i] + (out.user[i] - in.user[i]) * t;
    float* attrs = arena.alloc(params.attr_count);
    for (uint32_t i = 0; i < params.attr_count; ++i)
        attrs[i] = in.attrs[i] + (out.attrs[i] - in.attrs[i]) * t;
    r.attrs = attrs;
    return r;
}

// Puts a clipped vertex exactly on the frustum plane it was clipped to. The
// interpolation in+(out-in)*t cancels catastrophically for huge coordinates:
// clipping (-1e30,-1e30,0,1)..(0,1e30,0,1) against y = w gives y = 0, not 1,
// and half the triangle goes missing. The snap is a function of the vertex
// alone, so edges shared by two triangles still clip to the same point.
void snap_to_plane(ClipVertex& v, int plane, float guard) {
    glm::vec4& p = v.pos;
    switch (plane) {
    case 0: p.z = -p.w; break;
    case 1: p.z = p.w; break;
    case 2: p.x = guard * p.w; break;
    case 3: p.x = -guard * p.w; break;
    case 4: p.y = guard * p.w; break;
    case 5: p.y = -guard * p.w; break;
    default: v.user[plane - kFrustumPlanes] = 0.0f; break;
    }
}

ClipVertex clip_edge(const ClipVertex& in, const ClipVertex& out, float d_in, float d_out, int plane,
                     const ClipParams& params, AttrArena& arena) {
    ClipVertex r = lerp_vertex(in, out, d_in / (d_in - d_out), params, arena);
    snap_to_plane(r, plane, params.guard);
    return r;
}

}  // namespace

uint32_t outcode(const ClipVertex& v, const ClipParams& params) {
    uint32_t code = 0;
    for (int plane = 0; plane < kFrustumPlanes + kMaxUserPlanes; ++plane)
        if (plane_active(plane, params) && !(plane_distance(v, plane, params.guard) >= 0.0f))
            code |= 1u << plane;
    return code;
}

void clip_polygon(ClipPolygon& poly, const ClipParams& params, AttrArena& arena) {
    ClipPolygon next;
    for (int plane = 0; plane < kFrustumPlanes + kMaxUserPlanes && poly.size() >= 3; ++plane) {
        if (!plane_active(plane, params)) continue;
        next.clear();
        for (size_t i = 0; i < poly.size(); ++i) {
            const ClipVertex& a = poly[i];
            const ClipVertex& b = poly[(i + 1) % poly.size()];
            float da = plane_distance(a, plane, params.guard), db = plane_distance(b, plane, params.guard);
            bool a_in = da >= 0.0f, b_in = db >= 0.0f;
            if (a_in) next.push_back(a);
            if (a_in != b_in) {
                const ClipVertex& in = a_in ? a : b;
                const ClipVertex& out = a_in ? b : a;
                float d_in = a_in ? da : db, d_out = a_in ? db : da;
                ClipVertex cut = clip_edge(in, out, d_in, d_out, plane, params, arena);
                cut.edge = a_in ? plane >= kFrustumPlanes : a.edge;
                next.push_back(cut);
            }
        }
        poly = next;
    }
}

bool clip_segment(ClipVertex& a, ClipVertex& b, const ClipParams& params, AttrArena& arena) {
    for (int plane = 0; plane < kFrustumPlanes + kMaxUserPlanes; ++plane) {
        if (!plane_active(plane, params)) continue;
        float da = plane_distance(a, plane, params.guard), db = plane_distance(b, plane, params.guard);
        bool a_in = da >= 0.0f, b_in = db >= 0.0f;
        if (!a_in && !b_in) return false;
        if (a_in && b_in) continue;
        ClipVertex& out = a_in ? b : a;
        const ClipVertex& in = a_in ? a : b;
        float d_in = a_in ? da : db, d_out = a_in ? db : da;
        out = clip_edge(in, out, d_in, d_out, plane, params, arena);
    }
    return true;
}

}  // namespace glslrun::raster
