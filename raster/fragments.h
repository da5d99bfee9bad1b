// The fragment stage: packs 2x2 quads from any primitive into batches of
// kLanes/4 quads, interpolates the fragment shader's inputs (perspective
// correct) from per-primitive plane equations over whole lane arrays, runs
// the shader, then depth-tests and writes the covered, alive lanes in
// submission order, so results do not depend on the batch size.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "glslrun/glslrun.h"
#include "ir/ir.h"
#include "ir/scalar_ops.h"
#include "raster/fragment_ops.h"
#include "raster/probe.h"
#include "raster/quad_lanes.h"
#include "raster/triangle.h"
#include "runtime/backend.h"
#include "raster/fused/pipeline.h"

namespace glslrun::raster {

struct FsVertex {
    glm::vec2 win{0.0f};
    float z = 0;       // window depth
    float inv_w = 1;   // 1 / w_clip
    const float* attrs = nullptr;  // the stage's attribute vector (attr_count() floats)
};

// A screen-space linear function: at the centre of pixel (x, y) it is
// c + a * (x - ox) + b * (y - oy), with (ox, oy) the primitive's origin.
// The origin keeps the terms small, so that float evaluation stays accurate.
struct Plane {
    float a = 0, b = 0, c = 0;
};

struct FsPrimitive {
    std::array<FsVertex, 3> v;  // lines repeat vertex 1, points vertex 0
    int count = 3;  // 1 point, 2 line, 3 triangle
    bool front = true;
    // Points only (set_point_square): the pixels of the square before the
    // scissor, and gl_PointCoord = fma(step, (x, y), origin) at pixel (x, y):
    // llvmpipe's plane equations, evaluated as it does (one rounding).
    Rect point_box;
    glm::vec2 point_coord_origin{0.0f}, point_coord_step{0.0f};
    int line_width = 1;  // lines only: whole pixels (line_pixels)
    // Interpolation (set_*_planes): the screen-space (linear) weights of the
    // three vertices, and the window depth.
    int ox = 0, oy = 0;
    std::array<Plane, 3> weight;
    Plane z;
    // Triangles: the coverage of a small one (small triangles that cover
    // nothing are not kept); mask 0 for the others, whose edges the draw
    // keeps for the tiles' block walk.
    SmallCoverage cover;
    const TriangleEdges* edges = nullptr;
    // Which primitive of the draw (raster/assemble.h's order) and the
    // indices of its vertices, for the shader debugger (raster/probe.h).
    uint32_t primitive = 0;
    std::array<uint32_t, 3> vertex_ids{};
};

// `snapped`: the attribute weights from the positions snapped to the
// subpixel grid, as NVIDIA's driver interpolates (Precision::Fast); else from
// the unsnapped positions, as llvmpipe does.
void set_triangle_planes(FsPrimitive& prim, const TriangleSetup& setup, bool snapped = false);
void set_line_planes(FsPrimitive& prim);
void set_point_planes(FsPrimitive& prim);

// How the stage's attribute vector maps onto VS outputs; one entry per
// fragment input fed by a varying.
struct VaryingSlot {
    uint32_t offset = 0, count = 0;
    int vs_output = -1, vs_back_output = -1;
    bool is_color = false;
};

class FragmentStage {
public:
    FragmentStage(const Program& program, const GLState& gl, Framebuffer& fb, rt::DrawBudget* budget);
    ~FragmentStage();

    // A tile walk: while it lives, the stage's batches run with denormals
    // flushed (ir::FlushDenormals), their inputs and per-fragment operations
    // as well as the shader, as llvmpipe's fragment threads run; the mode is
    // switched once per walk, not twice per batch (rt::Executor::
    // hold_denormal_mode). Where the shader keeps denormals (Reference),
    // nothing is flushed. Both the C++ and the fused path run inside it,
    // and the quads queued in a walk are flushed in it (render_tile does).
    class Walk {
    public:
        explicit Walk(FragmentStage& stage);
        ~Walk();
        Walk(const Walk&) = delete;
        Walk& operator=(const Walk&) = delete;

    private:
        FragmentStage& stage_;
        std::optional<ir::FlushDenormals> flushed_;
    };

    uint32_t attr_count() const { return attr_count_; }
    // The attribute vector of one vertex from its VS outputs; colours clamped
    // to [0,1], back colours taken when `back` is set.
    void gather(const float* vs_vertex, const std::vector<uint32_t>& vs_offset, bool back, float* dst) const;
    // Copies the colour attributes of `from` into `to` (flat shading).
    void copy_colors(const float* from, float* to) const;

    // Queues a quad of `prim` (which must stay alive until flush()). With the
    // early tests, the stencil and depth tests and their writes happen here.
    void add_quad(const FsPrimitive& prim, int x, int y, unsigned mask);
    // add_quad() for each quad visit_quads(pixels, part, ox, oy) visits; the
    // fused pipeline tests the early depth of the part's pixels in one call.
    void add_quads(const FsPrimitive& prim, uint64_t pixels, uint64_t part, int ox, int oy);
    // Asks the caches for the depth and colour of the pixels of r, which
    // the stage is about to render (a tile): their misses overlap instead
    // of stalling one quad at a time.
    void prefetch(const Rect& r) const;
    // Shades what is pending; after a shader error, error() holds it and
    // further quads are ignored until clear_error().
    void flush();
    const std::optional<Error>& error() const { return error_; }
    void clear_error() { error_.reset(); }
    // Fragment counts of this stage so far.
    uint64_t fragments_shaded() const { return shaded_; }
    uint64_t fragments_written() const { return written_; }
    // Fast interpolates over the snapped triangle, as NVIDIA's driver does
    // (docs/precision.md, "The GPU's interpolation").
    bool snapped_planes() const { return program_.exec.precision == Precision::Fast; }
    // Of the fragments shaded, those the fused pipeline (raster/fused/pipeline.h) handled.
    uint64_t fragments_fused() const { return fused_; }

private:
    struct InputPlan;
    struct Weights;
    template <bool kWrite>
    unsigned depth_test_quad(int base, const float* z_lanes, unsigned mask);
    unsigned early_tests_quad(const FsPrimitive& prim, int base, unsigned mask);
    void compute_weights(Weights& w) const;
    void interpolate(uint32_t attr, const Weights& w, float* v) const;
    void builtin_input(fused::InputSource source, uint32_t c, const Weights& w, Lanes& v) const;
    void replace_sprite_coord(uint32_t c, const Weights& w, Lanes& v) const;
    void fill_inputs(const Weights& w);
    template <bool kProbed>
    rt::LaneMask write_outputs(rt::LaneMask covered);
    template <bool kProbed>
    rt::LaneMask write_plain(rt::LaneMask alive, const Lanes& z);
    rt::LaneMask write_watched(rt::LaneMask covered, rt::LaneMask alive, const Lanes& z);
    void snapshot(int lane, ProbePixel& pixel) const;
    void store_color_quad(int base, const std::array<Lanes, 4>& rgba, unsigned mask);
    rt::LaneMask write_with_ops(rt::LaneMask alive, const Lanes& z, ProbeTests* tests);
    rt::LaneMask stencil_depth_probed(const LanePixels& px, rt::LaneMask alive, ProbeTests& tests);
    void load_color(int buffer, std::array<Lanes, 4>& rgba) const;
    ProbeBatch probe_batch(rt::LaneMask covered);
    fused::State fused_state();
    const fused::Pipeline* fused_pipeline();

    const Program& program_;
    const GLState& gl_;
    Framebuffer& fb_;
    std::unique_ptr<rt::Executor> interp_;
    std::vector<InputPlan> inputs_;
    std::vector<VaryingSlot> varyings_;
    uint32_t attr_count_ = 0;
    FragmentOps ops_;
    // Per colour buffer: gl_FragData[i], or gl_FragColor for all; null: not written.
    std::array<const ir::Binding*, kMaxDrawBuffers> color_out_{};
    const ir::Binding* depth_out_ = nullptr;
    // Depth and stencil tested in add_quad: no discard, gl_FragDepth or alpha test.
    bool early_depth_ = false;
    // The early tests are all the draw does: no colour is written, nothing shaded.
    bool tests_only_ = false;
    int quads_ = 0;
    std::array<const FsPrimitive*, rt::kLanes / 4> quad_prim_{};
    std::array<int, rt::kLanes> lane_x_{}, lane_y_{};
    std::array<float, rt::kLanes> lane_z_{};
    rt::LaneMask covered_ = 0;
    uint64_t shaded_ = 0, written_ = 0, fused_ = 0;
    // The fused path: the JIT's pipeline for this draw's state, or null (the
    // C++ path above); its batch, buffers and the registers it fills and reads.
    const fused::Pipeline* pipeline_ = nullptr;
    fused::QuadBatch batch_;
    fused::Target target_;
    std::vector<uint32_t*> input_regs_;
    std::vector<const uint32_t*> output_regs_;
    std::optional<Error> error_;
    DrawProbe* probe_ = nullptr;
    std::unique_ptr<ProbeTests> probe_tests_;  // the batch's test outcomes, with a probe only
    bool skip_helper_lookups_ = false;  // helper lanes skip texture lookups (ir::Shader::helper_lookups_matter)
};

}  // namespace glslrun::raster
