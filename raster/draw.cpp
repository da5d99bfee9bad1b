// draw(): vertex shading, primitive assembly, clipping, the viewport
// transform, facing and culling, then triangles/lines/points into the
// fragment stage.
#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "raster/assemble.h"
#include "raster/clip.h"
#include "raster/fragments.h"
#include "raster/points_lines.h"
#include "raster/triangle.h"
#include "runtime/execute.h"

namespace glslrun {
namespace raster {
namespace {

int find_output(const ir::Shader& vs, const char* name) {
    for (size_t i = 0; i < vs.outputs.size(); ++i)
        if (vs.outputs[i].name == name) return int(i);
    return -1;
}

struct DrawContext {
    const GLState& gl;
    FragmentStage& stage;
    const exec::VertexOutputs& vs;
    std::vector<ClipVertex> vertices;  // per vertex of the arrays
    Rect scissor;
    glm::vec4 viewport;  // x y w h
    ClipParams clip;
    int point_size_output = -1;
    AttrArena arena;
};

FsVertex to_window(const DrawContext& c, const glm::vec4& clip) {
    FsVertex v;
    float inv_w = 1.0f / clip.w;
    glm::vec3 ndc = glm::vec3(clip) * inv_w;
    v.win.x = (ndc.x + 1.0f) * c.viewport[2] * 0.5f + c.viewport[0];
    v.win.y = (ndc.y + 1.0f) * c.viewport[3] * 0.5f + c.viewport[1];
    float n = c.gl.depth_near, f = c.gl.depth_far;
    v.z = std::clamp((ndc.z * (f - n) + (f + n)) * 0.5f, std::min(n, f), std::max(n, f));
    v.inv_w = inv_w;
    return v;
}

// The FS attribute vector of a (possibly clipped) vertex.
float* fs_attrs(DrawContext& c, const float* vs_attrs, bool back) {
    float* dst = c.arena.alloc(c.stage.attr_count());
    c.stage.gather(vs_attrs, c.vs.offset, back, dst);
    return dst;
}

// Gives every vertex the provoking vertex's colours (glShadeModel(GL_FLAT)).
void set_attrs(DrawContext& c, const std::vector<const float*>& vs_attrs, uint32_t provoking_id, bool back,
               std::vector<FsVertex>& verts) {
    const float* flat = c.gl.flat_shading ? fs_attrs(c, c.vertices[provoking_id].attrs, back) : nullptr;
    for (size_t i = 0; i < verts.size(); ++i) {
        float* attrs = fs_attrs(c, vs_attrs[i], back);
        if (flat) c.stage.copy_colors(flat, attrs);
        verts[i].attrs = attrs;
    }
}

double signed_area(const std::vector<FsVertex>& poly) {
    double sum = 0;
    for (size_t i = 0; i < poly.size(); ++i) {
        const glm::vec2& a = poly[i].win;
        const glm::vec2& b = poly[(i + 1) % poly.size()].win;
        sum += double(a.x) * b.y - double(b.x) * a.y;
    }
    return sum;
}

void rasterize_triangle(DrawContext& c, const FsPrimitive& prim) {
    std::array<glm::vec2, 3> win{prim.v[0].win, prim.v[1].win, prim.v[2].win};
    auto setup = setup_triangle(win, c.scissor);
    if (!setup) return;
    for_each_quad(*setup, c.scissor, [&](int x, int y, unsigned mask) {
        std::array<glm::dvec3, 4> weights;
        for (int i = 0; i < 4; ++i) weights[i] = barycentric(*setup, x + kQuadDx[i], y + kQuadDy[i]);
        c.stage.add_quad(prim, x, y, mask, weights);
    });
}

void draw_triangle(DrawContext& c, const std::array<uint32_t, 3>& ids, uint32_t provoking_id) {
    std::vector<ClipVertex> poly{c.vertices[ids[0]], c.vertices[ids[1]], c.vertices[ids[2]]};
    uint32_t codes[3] = {outcode(poly[0], c.clip), outcode(poly[1], c.clip), outcode(poly[2], c.clip)};
    if (codes[0] & codes[1] & codes[2]) return;
    if (codes[0] | codes[1] | codes[2]) clip_polygon(poly, c.clip, c.arena);
    if (poly.size() < 3) return;
    std::vector<FsVertex> verts;
    for (const ClipVertex& v : poly) verts.push_back(to_window(c, v.pos));
    double area = signed_area(verts);
    if (!(area != 0.0)) return;  // degenerate or NaN
    bool front = (area > 0) == c.gl.front_ccw;
    if (c.gl.cull_face && front != c.gl.cull_back) return;
    bool back_colors = c.gl.vertex_program_two_side && !front;
    std::vector<const float*> vs_attrs;
    for (const ClipVertex& v : poly) vs_attrs.push_back(v.attrs);
    set_attrs(c, vs_attrs, provoking_id, back_colors, verts);
    for (size_t k = 1; k + 1 < verts.size(); ++k) {
        FsPrimitive prim;
        prim.v = {verts[0], verts[k], verts[k + 1]};
        prim.front = front;
        rasterize_triangle(c, prim);
    }
}

void draw_line(DrawContext& c, const std::array<uint32_t, 3>& ids, uint32_t provoking_id) {
    ClipVertex a = c.vertices[ids[0]], b = c.vertices[ids[1]];
    uint32_t ca = outcode(a, c.clip), cb = outcode(b, c.clip);
    if (ca & cb) return;
    if ((ca | cb) && !clip_segment(a, b, c.clip, c.arena)) return;
    std::vector<FsVertex> verts{to_window(c, a.pos), to_window(c, b.pos)};
    set_attrs(c, {a.attrs, b.attrs}, provoking_id, false, verts);
    FsPrimitive prim;
    prim.v = {verts[0], verts[1], verts[1]};
    prim.count = 2;
    rasterize_line(c.stage, prim, c.scissor);
}

void draw_point(DrawContext& c, uint32_t id) {
    const ClipVertex& v = c.vertices[id];
    ClipParams frustum = c.clip;
    frustum.guard = 1.0f;  // a point is dropped when its centre is outside the view volume
    if (outcode(v, frustum)) return;
    FsPrimitive prim;
    prim.v[0] = to_window(c, v.pos);
    prim.v[0].attrs = fs_attrs(c, v.attrs, false);
    prim.count = 1;
    prim.point_center = prim.v[0].win;
    prim.point_size = c.gl.point_size;
    if (c.point_size_output >= 0) prim.point_size = v.attrs[c.vs.offset[size_t(c.point_size_output)]];
    rasterize_point(c.stage, prim, c.scissor);
}

std::vector<ClipVertex> make_clip_vertices(const ir::Shader& vs, const exec::VertexOutputs& out,
                                           uint32_t count, const GLState& gl) {
    int position = find_output(vs, "gl_Position");
    int clip_vertex = find_output(vs, "gl_ClipVertex");
    int plane_source = clip_vertex >= 0 ? clip_vertex : position;
    std::vector<ClipVertex> verts(count);
    for (uint32_t i = 0; i < count; ++i) {
        const float* attrs = out.vertex(i);
        ClipVertex& v = verts[i];
        v.attrs = attrs;
        if (position >= 0) {
            const float* p = attrs + out.offset[size_t(position)];
            v.pos = {p[0], p[1], p[2], p[3]};
        }
        if (plane_source >= 0 && gl.clip_plane_enabled) {
            const float* p = attrs + out.offset[size_t(plane_source)];
            glm::vec4 eye{p[0], p[1], p[2], p[3]};
            for (int k = 0; k < kMaxUserPlanes; ++k) v.user[k] = glm::dot(gl.clip_planes[k], eye);
        }
    }
    return verts;
}

Rect scissor_rect(const GLState& gl, const Framebuffer& fb, glm::vec4* viewport) {
    int vx = gl.viewport[0], vy = gl.viewport[1], vw = gl.viewport[2], vh = gl.viewport[3];
    if (vw <= 0 || vh <= 0) vx = 0, vy = 0, vw = fb.width, vh = fb.height;
    *viewport = glm::vec4(vx, vy, vw, vh);
    return Rect{std::max(vx, 0), std::max(vy, 0), std::min(vx + vw, fb.width), std::min(vy + vh, fb.height)};
}

}  // namespace
}  // namespace raster

Result<DrawStats> draw(Program& program, const GLState& gl, Framebuffer& fb, Primitive prim,
                       const std::vector<VertexAttrib>& attribs, uint32_t vertex_count,
                       std::span<const uint32_t> indices) {
    using namespace raster;
    if (fb.color.size() != size_t(fb.width) * fb.height * 4 || fb.depth.size() != size_t(fb.width) * fb.height)
        return Error("framebuffer storage does not match its size");
    for (uint32_t index : indices)
        if (index >= vertex_count)
            return Error(fmt::format("index {} is out of range ({} vertices)", index, vertex_count));
    if (Status st = apply_builtin_uniforms(program, gl); !st) return st.error();
    DrawStats stats;
    using Clock = std::chrono::steady_clock;
    auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    auto start = Clock::now();
    auto shaded = exec::shade_vertices(program, attribs, vertex_count, gl);
    if (!shaded) return shaded.error();
    stats.vertex_seconds = seconds_since(start);
    auto raster_start = Clock::now();
    stats.vertices = vertex_count;
    const ir::Shader& vs = program.state().ir.vertex;
    FragmentStage stage(program, gl, fb, stats);
    DrawContext c{gl, stage, *shaded, make_clip_vertices(vs, *shaded, vertex_count, gl), {}, {}, {}, -1, {}};
    c.scissor = scissor_rect(gl, fb, &c.viewport);
    if (c.scissor.x0 >= c.scissor.x1 || c.scissor.y0 >= c.scissor.y1) return stats;
    c.clip.guard = std::max(1.0f, float(1 << 19) / std::max(c.viewport[2], c.viewport[3]));
    c.clip.user_planes = gl.clip_plane_enabled & ((1u << kMaxUserPlanes) - 1);
    c.clip.attr_count = shaded->stride;
    c.point_size_output = find_output(vs, "gl_PointSize");
    uint32_t stream = indices.empty() ? vertex_count : uint32_t(indices.size());
    auto id = [&](uint32_t position) { return indices.empty() ? position : indices[position]; };
    for (const AssembledPrim& p : assemble(prim, stream)) {
        if (stage.failed()) break;
        c.arena.clear();
        std::array<uint32_t, 3> ids{id(p.v[0]), id(p.v[1]), id(p.v[2])};
        if (p.count == 3) {
            ++stats.triangles;
            draw_triangle(c, ids, id(p.provoking));
        } else if (p.count == 2) {
            draw_line(c, ids, id(p.provoking));
        } else {
            draw_point(c, ids[0]);
        }
    }
    if (Status st = stage.finish(); !st) return st.error();
    stats.raster_seconds = std::max(0.0, seconds_since(raster_start) - stats.fragment_seconds);
    return stats;
}

DrawStats& DrawStats::operator+=(const DrawStats& o) {
    vertices += o.vertices;
    triangles += o.triangles;
    fragments_shaded += o.fragments_shaded;
    fragments_written += o.fragments_written;
    vertex_seconds += o.vertex_seconds;
    raster_seconds += o.raster_seconds;
    fragment_seconds += o.fragment_seconds;
    return *this;
}

}  // namespace glslrun
