// draw(): vertex shading, primitive assembly, clipping, the viewport
// transform, facing, culling and triangle setup, binning into tiles, then the
// tiles (raster/tiles.h) on the worker threads.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "raster/assemble.h"
#include "raster/clip.h"
#include "raster/fragments.h"
#include "raster/points_lines.h"
#include "raster/scratch.h"
#include "raster/stipple.h"
#include "raster/tiles.h"
#include "raster/triangle.h"
#include "runtime/api_checks.h"
#include "runtime/execute.h"
#include "runtime/parallel.h"

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
    const FragmentStage& stage;
    const exec::VertexOutputs& vs;
    const std::vector<ClipVertex>& vertices;  // per vertex of the arrays
    std::vector<uint32_t>& outcodes;          // per vertex of the arrays, against `clip`
    Rect scissor;
    glm::vec4 viewport;  // x y w h
    ClipParams clip;
    // The vertex output points take their size from, or -1: every point is
    // fixed_point_size.
    int point_size_output = -1;
    float fixed_point_size = 1;
    // Per vertex of the arrays: its fragment attribute vector (front colours).
    std::vector<float>& front_attrs;
    // Per vertex of the arrays: its window position, depth and 1/w, which
    // the triangles that need no clipping share (a vertex is in about six).
    std::vector<FsVertex>& window;
};

// Writes in place (attrs are set later): returned by value, the vertex went
// through memory and stalled the next loads (perf: a third of draw_polygon).
[[gnu::always_inline]] inline void to_window(const DrawContext& c, const glm::vec4& clip, FsVertex& v) {
    float inv_w = 1.0f / clip.w;
    glm::vec3 ndc = glm::vec3(clip) * inv_w;
    v.win.x = (ndc.x + 1.0f) * c.viewport[2] * 0.5f + c.viewport[0];
    v.win.y = (ndc.y + 1.0f) * c.viewport[3] * 0.5f + c.viewport[1];
    float n = c.gl.depth_near, f = c.gl.depth_far;
    v.z = std::clamp((ndc.z * (f - n) + (f + n)) * 0.5f, std::min(n, f), std::max(n, f));
    v.inv_w = inv_w;
}

// The FS attribute vector of a (possibly clipped) vertex. Unclipped vertices
// with front colours share the one computed per vertex of the arrays.
const float* fs_attrs(const DrawContext& c, SetupOut& out, const ClipVertex& v, bool back) {
    if (!back && v.source >= 0) return c.front_attrs.data() + size_t(v.source) * c.stage.attr_count();
    float* dst = out.arena.alloc(c.stage.attr_count());
    c.stage.gather(v.attrs, c.vs.offset, back, dst);
    return dst;
}

// Gives every vertex the provoking vertex's colours (glShadeModel(GL_FLAT)).
void set_attrs(const DrawContext& c, SetupOut& out, const ClipVertex* const* poly, size_t n, uint32_t provoking_id,
               bool back, FsVertex* verts) {
    if (!c.gl.flat_shading) {
        for (size_t i = 0; i < n; ++i) verts[i].attrs = fs_attrs(c, out, *poly[i], back);
        return;
    }
    const float* flat = fs_attrs(c, out, c.vertices[provoking_id], back);
    for (size_t i = 0; i < n; ++i) {
        const float* own = fs_attrs(c, out, *poly[i], back);
        float* attrs = out.arena.alloc(c.stage.attr_count());
        std::copy(own, own + c.stage.attr_count(), attrs);
        c.stage.copy_colors(flat, attrs);
        verts[i].attrs = attrs;
    }
}

double signed_area(const FsVertex* poly, size_t n) {
    double sum = 0;
    // Without `(i + 1) % n`: a division per vertex (perf).
    for (size_t i = 0; i < n; ++i) {
        const glm::vec2& a = poly[i].win;
        const glm::vec2& b = poly[i + 1 == n ? 0 : i + 1].win;
        sum += double(a.x) * b.y - double(b.x) * a.y;
    }
    return sum;
}

void bin(SetupOut& out, const FsPrimitive& p, const Rect& bounds) {
    out.prims.push_back(p);
    out.prims.back().primitive = out.current_primitive;
    out.prims.back().vertex_ids = out.current_ids;
    out.bounds.push_back(bounds);
}

void add_triangle(const DrawContext& c, SetupOut& out, const FsVertex& v0, const FsVertex& v1, const FsVertex& v2,
                  bool front) {
    TriangleSetup setup;
    if (!setup_triangle({v0.win, v1.win, v2.win}, c.scissor, setup)) return;
    auto small = small_coverage(setup);
    if (small && !small->mask) return;  // between pixel centres: no fragments
    FsPrimitive& p = out.prims.emplace_back();  // built in place: it is large
    if (small) p.cover = *small;
    else out.edges.push_back(setup);
    p.v = {v0, v1, v2};
    p.front = front;
    p.primitive = out.current_primitive;
    p.vertex_ids = out.current_ids;
    set_triangle_planes(p, setup, c.stage.snapped_planes());
    out.bounds.push_back(setup.bbox);
}

// How a polygon's edges and vertices are drawn in glPolygonMode's line and
// point modes: with the polygon's facing, its colours and its depth offset.
struct EdgeStyle {
    bool front = true;
    bool back_colors = false;
    float z_offset = 0;
    int64_t provoking = -1;  // a polygon's points: the vertex whose colours flat shading gives them
};

// GL 2.1 §3.5.5: factor * max(|dz/dx|, |dz/dy|) + units * r, r the smallest
// resolvable difference of a 24-bit depth buffer; when the mode's enable is on.
float polygon_offset(const GLState& gl, const FsVertex* v, PolygonMode mode) {
    bool on = mode == PolygonMode::Fill   ? gl.polygon_offset_fill
              : mode == PolygonMode::Line ? gl.polygon_offset_line
                                          : gl.polygon_offset_point;
    if (!on) return 0;
    double x1 = v[1].win.x - v[0].win.x, y1 = v[1].win.y - v[0].win.y, z1 = double(v[1].z) - v[0].z;
    double x2 = v[2].win.x - v[0].win.x, y2 = v[2].win.y - v[0].win.y, z2 = double(v[2].z) - v[0].z;
    double area = x1 * y2 - x2 * y1, slope = 0;
    if (area != 0) slope = std::max(std::fabs((z1 * y2 - z2 * y1) / area), std::fabs((x1 * z2 - x2 * z1) / area));
    constexpr double kDepthResolution = 1.0 / double(1 << 24);
    return float(slope * gl.polygon_offset_factor + kDepthResolution * gl.polygon_offset_units);
}

// A triangle of the arrays: its vertices and which of its edges are the drawn primitive's.
struct TriangleIds {
    std::array<uint32_t, 3> ids;
    uint8_t edges = 7;
};

void emit_segment(const DrawContext& c, SetupOut& out, const ClipVertex& a, const ClipVertex& b,
                  uint32_t provoking_id, const EdgeStyle& style);
void emit_point(const DrawContext& c, SetupOut& out, const ClipVertex& v, const EdgeStyle& style);

// glPolygonMode(GL_LINE / GL_POINT): the polygon's edges whose flag is set
// (bit k: poly[k] to poly[k + 1]), or their first vertices, in Mesa's order:
// an unclipped triangle's edges v2-v0, v0-v1, v1-v2 and points v0, v1, v2; a
// clipped polygon, drawn by Mesa as a fan, its edges from the first on and
// points v1, v0, v2, v3, ... The order decides the pixels two edges share.
void draw_unfilled(const DrawContext& c, SetupOut& out, const ClipVertex* const* poly, size_t n, uint32_t edges,
                   bool clipped, PolygonMode mode, uint32_t provoking_id, const EdgeStyle& style) {
    std::array<size_t, kMaxClipVertices> order;
    for (size_t k = 0; k < n; ++k) order[k] = k;
    if (!clipped && mode == PolygonMode::Line) order = {2, 0, 1};
    if (clipped && mode == PolygonMode::Point) {
        std::swap(order[0], order[1]);
        if (n == 3) order = {1, 2, 0};
    }
    for (size_t i = 0; i < n; ++i) {
        size_t k = order[i];
        if (!((edges >> k) & 1u)) continue;
        if (mode == PolygonMode::Line) emit_segment(c, out, *poly[k], *poly[(k + 1) % n], provoking_id, style);
        else emit_point(c, out, *poly[k], style);
    }
}

// A convex polygon of n <= N vertices in the view volume: facing, culling,
// polygon mode and offset, attributes, then a fan of triangles.
// `verts` holds the vertices' window positions.
template <size_t N>
void draw_polygon(const DrawContext& c, SetupOut& out, const ClipVertex* const* poly, std::array<FsVertex, N>& verts,
                  size_t n, uint32_t provoking_id, uint32_t edges, bool clipped) {
    double area = signed_area(verts.data(), n);
    if (!(area != 0.0)) return;  // degenerate or NaN
    bool front = (area > 0) == c.gl.front_ccw;
    if (c.gl.cull_face && (c.gl.cull_front_and_back || front != c.gl.cull_back)) return;
    bool back_colors = c.gl.vertex_program_two_side && !front;
    PolygonMode mode = c.gl.polygon_mode[front ? 0 : 1];
    float offset = polygon_offset(c.gl, verts.data(), mode);
    if (mode != PolygonMode::Fill)
        return draw_unfilled(c, out, poly, n, edges, clipped, mode, provoking_id,
                             {front, back_colors, offset, provoking_id});
    if (offset != 0.0f)
        for (size_t i = 0; i < n; ++i) verts[i].z += offset;
    out.stipple_counter = 0;  // as Mesa's stipple stage, which a filled polygon passes
    set_attrs(c, out, poly, n, provoking_id, back_colors, verts.data());
    for (size_t k = 1; k + 1 < n; ++k) add_triangle(c, out, verts[0], verts[k], verts[k + 1], front);
}

void draw_triangle(const DrawContext& c, SetupOut& out, const TriangleIds& tri, uint32_t provoking_id) {
    const std::array<uint32_t, 3>& ids = tri.ids;
    const ClipVertex* corners[3] = {&c.vertices[ids[0]], &c.vertices[ids[1]], &c.vertices[ids[2]]};
    uint32_t codes[3] = {c.outcodes[ids[0]], c.outcodes[ids[1]], c.outcodes[ids[2]]};
    const bool unfilled = c.gl.polygon_mode[0] != PolygonMode::Fill || c.gl.polygon_mode[1] != PolygonMode::Fill;
    ClipParams params = c.clip;
    // A polygon that needs clipping Mesa clips to the viewport's sides as
    // well, not to the guard band: in GL_POINT mode the vertices made there
    // are drawn, and stippled edges count from there.
    if (unfilled) params.guard = 1.0f;
    if (unfilled && c.gl.line_stipple)
        for (size_t k = 0; k < 3; ++k) codes[k] = outcode(*corners[k], params);
    if (codes[0] & codes[1] & codes[2]) return;
    if (!(codes[0] | codes[1] | codes[2])) {
        std::array<FsVertex, 3> verts{c.window[ids[0]], c.window[ids[1]], c.window[ids[2]]};
        return draw_polygon(c, out, corners, verts, 3, provoking_id, tri.edges, false);
    }
    ClipPolygon poly{*corners[0], *corners[1], *corners[2]};
    for (size_t k = 0; k < 3; ++k) poly[k].edge = (tri.edges >> k) & 1u;
    clip_polygon(poly, params, out.arena);
    if (poly.size() < 3) return;
    std::array<const ClipVertex*, kMaxClipVertices> clipped;
    std::array<FsVertex, kMaxClipVertices> verts;
    uint32_t edges = 0;
    for (size_t i = 0; i < poly.size(); ++i) {
        clipped[i] = &poly[i];
        to_window(c, poly[i].pos, verts[i]);
        edges |= uint32_t(poly[i].edge) << i;
    }
    draw_polygon(c, out, clipped.data(), verts, poly.size(), provoking_id, edges, true);
}

// A line's pixels lie within two pixels of its end points (the diamond rule
// moves an end by up to one pixel along the line), and a wide line's within
// half its width more.
Rect line_rect(const FsPrimitive& p) {
    glm::vec2 lo = glm::min(p.v[0].win, p.v[1].win), hi = glm::max(p.v[0].win, p.v[1].win);
    int reach = 2 + p.line_width / 2;
    return {pixel_floor(lo.x) - reach, pixel_floor(lo.y) - reach, pixel_floor(hi.x) + 1 + reach,
            pixel_floor(hi.y) + 1 + reach};
}

// The vertex at t of the way from a to b, every value linear in window
// space (window position, depth, 1/w and the attributes), as llvmpipe makes
// the ends of a stipple's runs.
FsVertex window_lerp(const DrawContext& c, SetupOut& out, const FsVertex& a, const FsVertex& b, float t) {
    auto lerp = [t](float x, float y) { return x + t * (y - x); };
    FsVertex v;
    v.win = {lerp(a.win.x, b.win.x), lerp(a.win.y, b.win.y)};
    v.z = lerp(a.z, b.z);
    v.inv_w = lerp(a.inv_w, b.inv_w);
    const uint32_t n = c.stage.attr_count();
    float* attrs = out.arena.alloc(n);
    for (uint32_t i = 0; i < n; ++i) attrs[i] = lerp(a.attrs[i], b.attrs[i]);
    v.attrs = attrs;
    return v;
}

// glLineStipple: the runs of the pattern, each a line of its own.
void emit_stippled(const DrawContext& c, SetupOut& out, const FsPrimitive& line) {
    for_each_stipple_run(line.v[0].win, line.v[1].win, c.gl.line_stipple_pattern, c.gl.line_stipple_repeat,
                         out.stipple_counter, [&](float t0, float t1) {
                             if (++out.stipple_runs > kMaxStippleRuns || out.count_runs_only) return;
                             FsPrimitive run = line;
                             if (t0 > 0.0f) run.v[0] = window_lerp(c, out, line.v[0], line.v[1], t0);
                             if (t1 < 1.0f) run.v[1] = window_lerp(c, out, line.v[0], line.v[1], t1);
                             set_line_planes(run);
                             bin(out, run, line_rect(run));
                         });
}

// A segment inside the view volume and the user planes.
void emit_segment(const DrawContext& c, SetupOut& out, const ClipVertex& a, const ClipVertex& b,
                  uint32_t provoking_id, const EdgeStyle& style) {
    const ClipVertex* ends[2] = {&a, &b};
    FsPrimitive p;
    p.count = 2;
    p.front = style.front;
    p.line_width = line_pixels(c.gl.line_width);
    to_window(c, a.pos, p.v[0]);
    to_window(c, b.pos, p.v[1]);
    p.v[0].z += style.z_offset;
    p.v[1].z += style.z_offset;
    set_attrs(c, out, ends, 2, provoking_id, style.back_colors, p.v.data());
    if (c.gl.line_stipple) return emit_stippled(c, out, p);
    set_line_planes(p);
    bin(out, p, line_rect(p));
}

void draw_line(const DrawContext& c, SetupOut& out, const std::array<uint32_t, 3>& ids, uint32_t provoking_id) {
    ClipVertex a = c.vertices[ids[0]], b = c.vertices[ids[1]];
    uint32_t ca = c.outcodes[ids[0]], cb = c.outcodes[ids[1]];
    ClipParams params = c.clip;
    if (c.gl.line_stipple) {
        // Mesa clips lines to the view volume itself, and its stipple
        // counts from where they enter it.
        params.guard = 1.0f;
        ca = outcode(a, params), cb = outcode(b, params);
    }
    if (ca & cb) return;
    if ((ca | cb) && !clip_segment(a, b, params, out.arena)) return;
    emit_segment(c, out, a, b, provoking_id, {});
}

// A point inside the guard band (a polygon's vertex in GL_POINT mode, which
// Mesa does not clip again, or a point whose centre is in the view volume).
void emit_point(const DrawContext& c, SetupOut& out, const ClipVertex& v, const EdgeStyle& style) {
    FsPrimitive p;
    p.front = style.front;
    to_window(c, v.pos, p.v[0]);
    p.v[0].z += style.z_offset;
    const ClipVertex* own = &v;
    if (style.provoking >= 0) set_attrs(c, out, &own, 1, uint32_t(style.provoking), style.back_colors, p.v.data());
    else p.v[0].attrs = fs_attrs(c, out, v, style.back_colors);
    p.count = 1;
    out.stipple_counter = 0;  // as Mesa's stipple stage, which a point passes
    float size = c.point_size_output >= 0 ? v.attrs[c.vs.offset[size_t(c.point_size_output)]] : c.fixed_point_size;
    set_point_square(p, p.v[0].win, size, c.gl.point_sprite, c.gl.point_sprite_coord_lower_left);
    set_point_planes(p);
    bin(out, p, p.point_box);
}

// GL_POINTS: dropped when the centre is outside the view volume.
void draw_point(const DrawContext& c, SetupOut& out, const ClipVertex& v) {
    ClipParams frustum = c.clip;
    frustum.guard = 1.0f;
    if (!outcode(v, frustum)) emit_point(c, out, v, {});
}

// GL 2.1 §3.3: points take the vertex shader's gl_PointSize with
// GL_VERTEX_PROGRAM_POINT_SIZE. GL's fixed-function stage writes one only
// with distance attenuation (Mesa's; its stand-in here computes it as Mesa
// does) and takes no notice of GL_VERTEX_PROGRAM_POINT_SIZE. Otherwise the
// size is glPointSize clamped to [min, max], the minimum first where they
// cross (Mesa's CLAMP); a shader that should write gl_PointSize and does
// not gets glPointSize itself, as in Mesa.
struct PointSizes {
    int output = -1;
    float fixed = 1;
};
PointSizes point_sizes(const ir::Program& program, const GLState& gl) {
    const bool attenuated = gl.point_distance_attenuation != glm::vec3(1, 0, 0);
    const bool from_shader = program.fixed_function_vertex ? attenuated : gl.vertex_program_point_size;
    if (from_shader) return {find_output(program.vertex, "gl_PointSize"), gl.point_size};
    return {-1, gl.point_size < gl.point_size_min   ? gl.point_size_min
                : gl.point_size > gl.point_size_max ? gl.point_size_max
                                                    : gl.point_size};
}

// Where a vertex's clip position and user-plane distances come from.
struct ClipSources {
    int position = -1, plane_source = -1;
};

void make_clip_vertex(const exec::VertexOutputs& out, const ClipSources& src, const GLState& gl, uint32_t i,
                      ClipVertex& v) {
    const float* attrs = out.vertex(i);
    v = ClipVertex{};
    v.attrs = attrs;
    v.source = int(i);
    if (src.position >= 0) {
        const float* p = attrs + out.offset[size_t(src.position)];
        v.pos = {p[0], p[1], p[2], p[3]};
    }
    if (src.plane_source >= 0 && gl.clip_plane_enabled) {
        const float* p = attrs + out.offset[size_t(src.plane_source)];
        glm::vec4 eye{p[0], p[1], p[2], p[3]};
        for (int k = 0; k < kMaxUserPlanes; ++k) v.user[k] = glm::dot(gl.clip_planes[k], eye);
    }
}

Rect scissor_rect(const GLState& gl, const Framebuffer& fb, glm::vec4* viewport) {
    int64_t vx = gl.viewport[0], vy = gl.viewport[1], vw = gl.viewport[2], vh = gl.viewport[3];
    if (vw <= 0 || vh <= 0) vx = 0, vy = 0, vw = fb.width, vh = fb.height;
    *viewport = glm::vec4(float(vx), float(vy), float(vw), float(vh));
    // 64-bit: x + width may pass INT_MAX.
    auto clamp_to = [](int64_t v, int hi) { return int(std::clamp<int64_t>(v, 0, hi)); };
    Rect r{clamp_to(vx, fb.width), clamp_to(vy, fb.height), clamp_to(vx + vw, fb.width), clamp_to(vy + vh, fb.height)};
    if (!gl.scissor_test) return r;
    // glScissor (GL 2.1 §4.1.2); in 64 bits too.
    const auto& box = gl.scissor_box;
    auto lo = [](int v, int bound) { return std::max(v, bound); };
    auto hi = [](int v, int64_t size, int bound) { return int(std::min<int64_t>(int64_t(v) + std::max<int64_t>(size, 0), bound)); };
    return Rect{lo(box[0], r.x0), lo(box[1], r.y0), hi(box[0], box[2], r.x1), hi(box[1], box[3], r.y1)};
}

// What GL would refuse with GL_INVALID_ENUM / GL_INVALID_VALUE, and a
// framebuffer whose size was refused.
Status check_draw_input(const GLState& gl, const Framebuffer& fb, Primitive prim) {
    if (fb.width <= 0 || fb.height <= 0)
        return Error("the framebuffer is empty: its size was refused (Framebuffer::create says why)");
    if (!storage_matches(fb)) return Error("framebuffer storage does not match its size");
    if (gl.draw_buffers < 1 || gl.draw_buffers > fb.color_buffers())
        return Error(fmt::format("glDrawBuffers names {} colour buffers; the framebuffer has {}", gl.draw_buffers,
                                 fb.color_buffers()));
    if (!rt::enum_in_range(prim, Primitive::Polygon))
        return Error(fmt::format("primitive {} is not a GL primitive (GL_INVALID_ENUM)", int(prim)));
    if (Status st = rt::check_gl_enums(gl); !st) return st;
    if (!(gl.line_width > 0.0f))
        return Error(fmt::format("line width {} must be > 0 (GL_INVALID_VALUE)", gl.line_width));
    for (float v : {gl.point_size_min, gl.point_size_max, gl.point_fade_threshold_size})
        if (!(v >= 0.0f))
            return Error(fmt::format("point parameter {} (size min, max or fade threshold) must be >= 0 "
                                     "(GL_INVALID_VALUE)", v));
    if (gl.viewport[2] < 0 || gl.viewport[3] < 0)
        return Error(fmt::format("viewport {}x{}: width and height must not be negative (GL_INVALID_VALUE)",
                                 gl.viewport[2], gl.viewport[3]));
    return Ok{};
}

// The draw's storage per vertex: the shaded outputs, the fragment
// attributes (at most as many), and the clip and window vertices.
Status check_draw_size(const ir::Shader& vs, uint64_t vertex_count, uint64_t index_count) {
    uint64_t outputs = 0;
    for (const ir::Binding& b : vs.outputs) outputs += b.count;
    const uint64_t words = 2 * outputs + (sizeof(ClipVertex) + sizeof(FsVertex) + sizeof(uint32_t)) / 4;
    if (Status st = rt::check_batch_size(vertex_count, words, "vertices"); !st) return st;
    return rt::check_batch_size(index_count, 1, "indices");
}

// Vertices per job of prepare(), and the count below which it stays on the
// calling thread. A worker starts in about 50 to 90 us (2-vCPU machine), and
// a vertex's clip vertex, outcode and attributes take tens of ns.
constexpr uint32_t kPrepareJob = 2048;
constexpr uint32_t kParallelPrepare = 2 * kPrepareJob;

// Clip parameters, then per vertex of the arrays its clip vertex, outcode
// and fragment attribute vector: on the workers for large draws (each
// vertex's results are its own, so they do not depend on the thread count).
void prepare(DrawContext& c, const ir::Shader& vs, uint32_t vertex_count, unsigned threads,
             std::vector<ClipVertex>& vertices) {
    c.clip.guard = std::max(1.0f, float(1 << 19) / std::max(c.viewport[2], c.viewport[3]));
    c.clip.user_planes = c.gl.clip_plane_enabled & ((1u << kMaxUserPlanes) - 1);
    c.clip.attr_count = c.vs.stride;
    ClipSources src;
    src.position = find_output(vs, "gl_Position");
    int clip_vertex = find_output(vs, "gl_ClipVertex");
    src.plane_source = clip_vertex >= 0 ? clip_vertex : src.position;
    const uint32_t n = c.stage.attr_count();
    vertices.resize(vertex_count);
    c.outcodes.resize(vertex_count);
    c.front_attrs.resize(size_t(vertex_count) * n);
    c.window.resize(vertex_count);
    size_t jobs = (size_t(vertex_count) + kPrepareJob - 1) / kPrepareJob;
    unsigned workers = vertex_count < kParallelPrepare ? 1 : rt::thread_count(threads, jobs);
    rt::JobQueue queue(jobs);
    rt::run_workers(workers, [&](unsigned) {
        for (size_t job; queue.next(&job);) {
            uint32_t end = uint32_t(std::min<size_t>(vertex_count, (job + 1) * kPrepareJob));
            for (uint32_t v = uint32_t(job) * kPrepareJob; v < end; ++v) {
                make_clip_vertex(c.vs, src, c.gl, v, vertices[v]);
                c.outcodes[v] = outcode(vertices[v], c.clip);
                to_window(c, vertices[v].pos, c.window[v]);
                c.stage.gather(c.vs.vertex(v), c.vs.offset, false, c.front_attrs.data() + size_t(v) * n);
            }
        }
    });
}

// Primitives per setup job, and the draw size below which setup stays on
// the calling thread. A triangle's setup takes about 100 ns, so a draw of a
// few thousand pays for a worker's start (50 to 90 us): at 8192 per job the
// 13,040 triangles of the toon teapot (1.3 ms) stayed on one thread, a fifth
// of its 2-thread frame.
constexpr size_t kSetupJob = 2048;
constexpr size_t kParallelSetup = 2 * kSetupJob;

void set_up_range(const DrawContext& c, SetupOut& out, const std::vector<AssembledPrim>& assembled, bool triangles,
                  size_t begin, size_t end, std::span<const uint32_t> indices) {
    auto id = [&](uint32_t position) { return indices.empty() ? position : indices[position]; };
    out.prims.reserve(end - begin);
    out.bounds.reserve(end - begin);
    for (size_t i = begin; i < end; ++i) {
        // GL_TRIANGLES, the commonest mode, without the array (raster/assemble.h).
        const AssembledPrim p = triangles ? triangle_at(uint32_t(i)) : assembled[i];
        std::array<uint32_t, 3> ids{id(p.v[0]), id(p.v[1]), id(p.v[2])};
        out.current_primitive = uint32_t(i);
        out.current_ids = ids;
        if (p.restarts_stipple) out.stipple_counter = 0;
        if (p.count == 3) {
            ++out.triangles;
            draw_triangle(c, out, {ids, p.edges}, id(p.provoking));
        } else if (p.count == 2) {
            draw_line(c, out, ids, id(p.provoking));
        } else {
            draw_point(c, out, c.vertices[ids[0]]);
        }
    }
}

// Assembles, clips and sets up every primitive, in jobs on the workers when
// there are many; `outs` keeps the jobs' attribute storage.
std::span<SetupOut> set_up_primitives(const DrawContext& c, Primitive prim, uint32_t vertex_count,
                                       std::span<const uint32_t> indices, unsigned threads, DrawScratch& scratch,
                                       bool count_runs_only = false) {
    uint32_t stream = indices.empty() ? vertex_count : uint32_t(indices.size());
    std::vector<AssembledPrim>& assembled = scratch.assembled;
    const bool triangles = prim == Primitive::Triangles;  // the same either way in the unfilled modes
    bool unfilled = c.gl.polygon_mode[0] != PolygonMode::Fill || c.gl.polygon_mode[1] != PolygonMode::Fill;
    // Polygon stipple, too, sends Mesa's polygons through its draw pipeline,
    // which splits quads and polygons the unfilled way.
    if (triangles) assembled.clear();
    else assemble(prim, stream, assembled, unfilled || c.gl.polygon_stipple);
    const size_t count = triangles ? stream / 3 : assembled.size();
    size_t jobs = (count + kSetupJob - 1) / kSetupJob;
    // The line stipple's counter runs on from primitive to primitive.
    unsigned workers = count < kParallelSetup || c.gl.line_stipple ? 1 : rt::thread_count(threads, jobs);
    // One thread: one job, whose primitives need no copy. A primitive's setup
    // does not depend on its job, so neither do the results.
    size_t job_size = workers == 1 ? std::max<size_t>(count, 1) : kSetupJob;
    jobs = std::max<size_t>(1, (count + job_size - 1) / job_size);
    if (scratch.setup.size() < jobs) scratch.setup.resize(jobs);
    std::span<SetupOut> outs(scratch.setup.data(), jobs);
    for (SetupOut& out : outs) {
        out.clear();
        out.count_runs_only = count_runs_only;
    }
    rt::JobQueue queue(jobs);
    rt::run_workers(workers, [&](unsigned) {
        for (size_t job; queue.next(&job);)
            set_up_range(c, outs[job], assembled, triangles, job * job_size, std::min(count, (job + 1) * job_size),
                         indices);
    });
    return outs;
}

// Bins the jobs' primitives in submission order, where the jobs left them,
// and points the large triangles at their edges.
void bin_primitives(std::span<SetupOut> outs, TileBins& bins, uint64_t* triangles) {
    *triangles = 0;
    for (SetupOut& out : outs) {
        *triangles += out.triangles;
        size_t large = 0;
        for (size_t i = 0; i < out.prims.size(); ++i) {
            FsPrimitive& p = out.prims[i];
            if (p.count == 3 && !p.cover.mask) p.edges = &out.edges[large++];
            bins.add(&p, out.bounds[i]);
        }
    }
}

// With two or three threads the tiles clear the whole target before any
// tile, on the calling thread (0.15 to 0.2 ms at 1080p, a serial part of
// every 2-thread frame). A draw whose vertices and setup take longer than
// that clears on a thread of its own while they run, and the tiles wait for
// it: the same pixels, cleared before any tile. Small draws and targets keep
// the tiles' clear, which costs less than starting a thread (50 to 90 us).
constexpr uint64_t kClearAheadVertices = 6144;  // about 2,000 triangles: 0.2 ms of setup
constexpr uint64_t kClearAheadPixels = 512 * 512;

class ClearAhead {
public:
    ClearAhead(Framebuffer& fb, const StoredClear* clear, unsigned threads, uint64_t vertices) : job_{&fb, clear} {
        const unsigned n = rt::thread_count(threads, SIZE_MAX);
        if (!clear || n < 2 || n >= kTileClearMinThreads || vertices < kClearAheadVertices ||
            uint64_t(fb.width) * uint64_t(fb.height) < kClearAheadPixels)
            return;
        thread_.emplace();
        auto run = [](void* p) {
            const Job& job = *static_cast<const Job*>(p);
            clear_rect(*job.fb, *job.clear, 0, 0, job.fb->width, job.fb->height);
        };
        if (!thread_->start(run, &job_)) thread_.reset();  // no thread: the tiles clear
    }
    ClearAhead(const ClearAhead&) = delete;
    ClearAhead& operator=(const ClearAhead&) = delete;
    // Whether the clear runs (or ran) here rather than in the tiles.
    bool started() const { return thread_.has_value(); }
    // Waits for the clear.
    void finish() { thread_.reset(); }

private:
    struct Job {
        Framebuffer* fb;
        const StoredClear* clear;
    };
    Job job_;  // read by the thread, which thread_ joins before job_ goes
    std::optional<rt::WorkerThreads> thread_;
};

// draw(), with the tiles clearing the framebuffer first where `clear` is
// given; *cleared says whether they did (they do unless draw() fails or
// returns before its tiles; a clear ahead always does).
Result<DrawStats> draw_tiles(Program& program, const GLState& gl, Framebuffer& fb, Primitive prim,
                             const std::vector<VertexAttrib>& attribs, uint32_t vertex_count,
                             std::span<const uint32_t> indices, const StoredClear* clear, bool* cleared) {
    ProgramUse use(program);
    if (!use.status()) return use.status().error();
    if (Status st = check_draw_input(gl, fb, prim); !st) return st.error();
    if (Status st = rt::check_exec_options(program.exec); !st) return st.error();
    if (Status st = check_draw_size(state_of(program).ir.vertex, vertex_count, indices.size()); !st) return st.error();
    for (uint32_t index : indices)
        if (index >= vertex_count)
            return Error(fmt::format("index {} is out of range ({} vertices)", index, vertex_count));
    if (Status st = apply_builtin_uniforms(program, gl); !st) return st.error();
    auto& scratch_ptr = state_of(program).draw_scratch;
    if (!scratch_ptr) scratch_ptr = std::make_shared<DrawScratch>();
    DrawScratch& scratch = *static_cast<DrawScratch*>(scratch_ptr.get());
    DrawStats stats;
    using Clock = std::chrono::steady_clock;
    auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    auto start = Clock::now();
    ClearAhead clear_ahead(fb, clear, program.exec.threads, indices.empty() ? vertex_count : indices.size());
    if (clear_ahead.started()) {
        *cleared = true;
        clear = nullptr;
    }
    rt::DrawBudget budget(program.exec);
    if (Status st = exec::shade_vertices(program, attribs, vertex_count, gl, scratch.shaded, budget); !st)
        return st.error();
    stats.vertex_seconds = seconds_since(start);
    if (raster::DrawProbe* probe = state_of(program).probe)
        probe->begin_draw(ProbeDraw{gl, attribs, vertex_count, scratch.shaded, &program});
    auto raster_start = Clock::now();
    stats.vertices = vertex_count;
    const ir::Shader& vs = state_of(program).ir.vertex;
    glm::vec4 viewport;
    Rect scissor = scissor_rect(gl, fb, &viewport);
    if (scissor.x0 < scissor.x1 && scissor.y0 < scissor.y1) {
        // The stage's executor goes at the end of this scope: its last instructions reach the budget.
        FragmentStage stage(program, gl, fb, &budget);
        std::optional<PolygonStipple> stipple;
        if (gl.polygon_stipple) stipple.emplace(gl.polygon_stipple_pattern);
        const PointSizes sizes = point_sizes(state_of(program).ir, gl);
        DrawContext c{gl, stage, scratch.shaded, scratch.vertices, scratch.outcodes, scissor, viewport,
                      {}, sizes.output, sizes.fixed, scratch.front_attrs, scratch.window};
        prepare(c, vs, vertex_count, program.exec.threads, scratch.vertices);
        // Stippled lines' dashes are counted before any is made (a stippled
        // draw sets up in one job): a draw past the limit fails without
        // storing them (the dashes of the lines clipped to the view volume,
        // as the draw makes them: no bound from the unclipped lengths).
        const bool lines = prim == Primitive::Lines || prim == Primitive::LineStrip || prim == Primitive::LineLoop ||
                           gl.polygon_mode[0] == PolygonMode::Line || gl.polygon_mode[1] == PolygonMode::Line;
        if (gl.line_stipple && lines &&
            set_up_primitives(c, prim, vertex_count, indices, program.exec.threads, scratch, true)[0].stipple_runs >
                kMaxStippleRuns)
            return Error(fmt::format("the draw's stippled lines make more than {} dashes (runs of the pattern's set "
                                     "bits), glslrun's limit per draw (docs/limits.md); draw fewer or shorter lines",
                                     kMaxStippleRuns));
        auto outs = set_up_primitives(c, prim, vertex_count, indices, program.exec.threads, scratch);
        scratch.bins.reset(scissor);
        bin_primitives(outs, scratch.bins, &stats.triangles);
        stats.raster_seconds = seconds_since(raster_start);
        auto fragment_start = Clock::now();
        clear_ahead.finish();
        TileResult tiles =
            scratch.bins.render(TileTarget{program, gl, fb, scissor, &budget, stipple ? &*stipple : nullptr}, stage,
                                program.exec.threads, clear);
        *cleared = true;
        stats.fragment_seconds = seconds_since(fragment_start);
        stats.fragments_shaded = tiles.fragments_shaded;
        stats.fragments_written = tiles.fragments_written;
        stats.fragments_fused = tiles.fragments_fused;
        if (!tiles.status) return tiles.status.error();
    }
    // Every executor has reported: the total decides, whatever the threads.
    stats.instructions = budget.used();
    if (budget.over() != rt::DrawBudget::Stop::None) return Error(budget.message(budget.over()));
    return stats;
}

}  // namespace
}  // namespace raster

Result<DrawStats> draw(Program& program, const GLState& gl, Framebuffer& fb, Primitive prim,
                       const std::vector<VertexAttrib>& attribs, uint32_t vertex_count,
                       Span<const uint32_t> indices) {
    bool cleared = false;
    return rt::without_throwing("draw()", [&] {
        return raster::draw_tiles(program, gl, fb, prim, attribs, vertex_count, indices, nullptr, &cleared);
    });
}

Result<DrawStats> draw(Program& program, const GLState& gl, Framebuffer& fb, const ClearValues& clear,
                       Primitive prim, const std::vector<VertexAttrib>& attribs, uint32_t vertex_count,
                       Span<const uint32_t> indices) {
    raster::StoredClear stored = raster::stored_clear(fb, clear);
    bool any = raster::storage_matches(fb) && (stored.color || stored.depth || stored.stencil);
    bool cleared = false;
    auto result = rt::without_throwing("draw()", [&] {
        return raster::draw_tiles(program, gl, fb, prim, attribs, vertex_count, indices, any ? &stored : nullptr,
                                  &cleared);
    });
    // Failed or empty draws clear as glClear did before them.
    if (!cleared || !any) {
        if (clear.color) fb.clear_color(*clear.color);
        if (clear.depth) fb.clear_depth(*clear.depth);
        if (clear.stencil) fb.clear_stencil(*clear.stencil);
    }
    return result;
}

DrawStats& DrawStats::operator+=(const DrawStats& o) {
    vertices += o.vertices;
    triangles += o.triangles;
    fragments_shaded += o.fragments_shaded;
    fragments_written += o.fragments_written;
    fragments_fused += o.fragments_fused;
    vertex_seconds += o.vertex_seconds;
    raster_seconds += o.raster_seconds;
    fragment_seconds += o.fragment_seconds;
    instructions += o.instructions;
    return *this;
}

}  // namespace glslrun
