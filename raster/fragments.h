// The fragment stage: packs 2x2 quads from any primitive into batches of
// kLanes/4 quads, interpolates the fragment shader's inputs (perspective
// correct), runs the shader, then depth-tests and writes the covered, alive
// lanes in submission order, so results do not depend on the batch size.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "glslrun/glslrun.h"
#include "ir/ir.h"
#include "raster/triangle.h"
#include "runtime/interpreter.h"

namespace glslrun::raster {

struct FsVertex {
    glm::vec2 win{0.0f};
    float z = 0;       // window depth
    float inv_w = 1;   // 1 / w_clip
    const float* attrs = nullptr;  // the stage's attribute vector (attr_count() floats)
};

struct FsPrimitive {
    std::array<FsVertex, 3> v;
    int count = 3;  // 1 point, 2 line, 3 triangle
    bool front = true;
    glm::vec2 point_center{0.0f};  // points only: window position and size
    float point_size = 1;
};

// How the stage's attribute vector maps onto VS outputs; one entry per
// fragment input fed by a varying.
struct VaryingSlot {
    uint32_t offset = 0, count = 0;
    int vs_output = -1, vs_back_output = -1;
    bool is_color = false;
};

class FragmentStage {
public:
    FragmentStage(const Program& program, const GLState& gl, Framebuffer& fb, DrawStats& stats);
    ~FragmentStage();

    uint32_t attr_count() const { return attr_count_; }
    // The attribute vector of one vertex from its VS outputs; colours clamped
    // to [0,1], back colours taken when `back` is set.
    void gather(const float* vs_vertex, const std::vector<uint32_t>& vs_offset, bool back, float* dst) const;
    // Copies the colour attributes of `from` into `to` (flat shading).
    void copy_colors(const float* from, float* to) const;

    // weights: screen-space linear weights of the primitive's vertices per lane.
    void add_quad(const FsPrimitive& prim, int x, int y, unsigned mask,
                  const std::array<glm::dvec3, 4>& weights);
    // Shades what is pending; returns the first shader error of the draw.
    Status finish();
    bool failed() const { return error_.has_value(); }

private:
    struct InputPlan;
    void fill_lane(const FsPrimitive& prim, int lane, int x, int y, const glm::dvec3& l);
    void flush();

    const Program& program_;
    const GLState& gl_;
    Framebuffer& fb_;
    DrawStats& stats_;
    std::unique_ptr<rt::Interpreter> interp_;
    std::vector<InputPlan> inputs_;
    std::vector<VaryingSlot> varyings_;
    uint32_t attr_count_ = 0;
    const ir::Binding* color_out_ = nullptr;
    const ir::Binding* depth_out_ = nullptr;
    int quads_ = 0;
    std::array<int, rt::kLanes> lane_x_{}, lane_y_{};
    std::array<float, rt::kLanes> lane_z_{};
    rt::LaneMask covered_ = 0;
    std::optional<Error> error_;
};

}  // namespace glslrun::raster
