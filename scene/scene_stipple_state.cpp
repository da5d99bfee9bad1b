// [state]'s point parameters and stipples: glPointParameter (GL 1.4's
// GL_POINT_SIZE_MIN/MAX, GL_POINT_DISTANCE_ATTENUATION,
// GL_POINT_FADE_THRESHOLD_SIZE, GL 2.0's GL_POINT_SPRITE_COORD_ORIGIN),
// glLineStipple and glPolygonStipple with their enables. Keys are GL's
// state-table names in snake_case (docs/scene-format.md).
#include <fmt/format.h>

#include "scene/scene_reader.h"

namespace glslrun::scene::detail {

namespace {

constexpr Range kPointParameter{.lo = 0, .why = "glPointParameter; GL_INVALID_VALUE below 0"};

void read_point_parameters(const Section& s, GLState& gl) {
    s.read("point_size_min", gl.point_size_min, kPointParameter);
    s.read("point_size_max", gl.point_size_max, kPointParameter);
    s.read("point_fade_threshold_size", gl.point_fade_threshold_size, kPointParameter);
    if (const toml::node* n = s.get("point_distance_attenuation")) {
        std::vector<double> abc = numbers(*n, s.name("point_distance_attenuation") + " ([constant, linear, quadratic])",
                                          3, 3);
        gl.point_distance_attenuation = glm::vec3(glm::dvec3(abc[0], abc[1], abc[2]));
    }
    if (const toml::node* n = s.get("point_sprite_coord_origin"))
        gl.point_sprite_coord_lower_left =
            choice(*n, s.name("point_sprite_coord_origin"), {"upper_left", "lower_left"}) == 1;
}

// glLineStipple(repeat, pattern). GL clamps the repeat to [1, 256] and keeps
// the pattern's low 16 bits; a value outside them is a mistake worth reporting.
void read_line_stipple(const Section& s, GLState& gl) {
    s.read("line_stipple", gl.line_stipple);
    if (const toml::node* n = s.get("line_stipple_repeat"))
        gl.line_stipple_repeat = int(integer(*n, s.name("line_stipple_repeat") + " (glLineStipple's factor)", 1, 256));
    if (const toml::node* n = s.get("line_stipple_pattern"))
        gl.line_stipple_pattern =
            uint16_t(integer(*n, s.name("line_stipple_pattern") + " (16 bits, as 0x0F0F)", 0, 0xFFFF));
}

// glPolygonStipple: 32 rows bottom up, each a 32-bit integer whose high bit
// is the leftmost pixel. Fewer rows (1, 2, 4, 8 or 16) repeat upwards.
void read_polygon_stipple(const Section& s, GLState& gl) {
    s.read("polygon_stipple", gl.polygon_stipple);
    const toml::node* n = s.get("polygon_stipple_pattern");
    if (!n) return;
    const std::string what = s.name("polygon_stipple_pattern");
    const toml::array& rows = array(*n, what);
    const size_t count = rows.size();
    if (count == 0 || count > 32 || 32 % count != 0)
        fail(*n, fmt::format("'{}' must be 32 rows (bottom up, each a 32-bit integer such as 0xAAAAAAAA), or "
                             "1, 2, 4, 8 or 16 rows that repeat; got {}",
                             what, describe(*n)));
    for (size_t i = 0; i < 32; ++i) {
        const toml::node& row = rows[i % count];
        gl.polygon_stipple_pattern[i] =
            uint32_t(integer(row, fmt::format("{}[{}] (a row of 32 bits)", what, i % count), 0, 0xFFFFFFFFll));
    }
}

}  // namespace

const std::vector<std::string_view>& stipple_state_keys() {
    static const std::vector<std::string_view> keys = {
        "point_size_min", "point_size_max", "point_distance_attenuation", "point_fade_threshold_size",
        "point_sprite_coord_origin", "line_stipple", "line_stipple_repeat", "line_stipple_pattern",
        "polygon_stipple", "polygon_stipple_pattern"};
    return keys;
}

void read_stipple_state(const Section& s, GLState& gl) {
    read_point_parameters(s, gl);
    read_line_stipple(s, gl);
    read_polygon_stipple(s, gl);
}

}  // namespace glslrun::scene::detail
