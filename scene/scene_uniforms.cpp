// User uniforms and attribute arrays. Uniforms are flattened into the names
// glUniform* takes ("a", "s.f", "lights[1].pos", "arr[2]") with their numbers
// in GL's order (vector components, matrix columns, array elements); the
// renderer matches them against the program's declarations.
#include <algorithm>

#include <fmt/format.h>

#include "scene/scene_reader.h"

namespace glslrun::scene::detail {

namespace {

bool reserved(std::string_view name) { return name.starts_with("gl_"); }

bool is_identifier(std::string_view s) {
    auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (s.empty() || !alpha(s[0])) return false;
    for (char c : s)
        if (!alpha(c) && !(c >= '0' && c <= '9')) return false;
    return true;
}

// Appends a scalar or a nested array of scalars to `u` and returns its shape
// (the length at each level), so that siblings can be compared: a matrix's
// columns, or an array's vectors, must all have the same length.
std::vector<size_t> collect(const toml::node& n, const std::string& what, UniformSetting& u, bool& any_bool) {
    if (auto b = n.as_boolean()) {
        any_bool = true;
        u.values.push_back(b->get() ? 1.0 : 0.0);
        return {};
    }
    if (n.is_number()) {
        u.integral = u.integral && n.is_integer();
        u.values.push_back(number(n, what));
        return {};
    }
    const toml::array* a = n.as_array();
    if (!a || a->empty())
        fail(n, fmt::format("uniform '{}' must hold numbers or booleans (got {})", what, describe(n)));
    std::vector<size_t> shape;
    for (size_t i = 0; i < a->size(); ++i) {
        std::vector<size_t> s = collect((*a)[i], fmt::format("{}[{}]", what, i), u, any_bool);
        if (i == 0) shape = s;
        else if (s != shape)
            fail((*a)[i], fmt::format("uniform '{}': every element must have the same shape as the first "
                                      "(vectors or columns of one length)", what));
    }
    shape.insert(shape.begin(), a->size());
    return shape;
}

// Settings with where they start in the file, so they can be put in file order.
using Placed = std::vector<std::pair<toml::source_position, UniformSetting>>;

void flatten(const toml::node& n, const std::string& name, Placed& out);

void flatten_table(const toml::table& t, const std::string& name, Placed& out) {
    if (t.empty()) fail(t, fmt::format("uniform struct '{}' is empty", name));
    for (auto&& [k, v] : t) flatten(v, fmt::format("{}.{}", name, k.str()), out);
}

void flatten(const toml::node& n, const std::string& name, Placed& out) {
    if (auto t = n.as_table()) return flatten_table(*t, name, out);
    const toml::array* a = n.as_array();
    if (a && !a->empty() && (*a)[0].is_table()) {
        // An array of structs: each element is one GL name prefix.
        for (size_t i = 0; i < a->size(); ++i) {
            std::string element = fmt::format("{}[{}]", name, i);
            if (!(*a)[i].is_table())
                fail((*a)[i], fmt::format("uniform '{}' must be a table like the elements before it",
                                          element));
            flatten_table(*(*a)[i].as_table(), element, out);
        }
        return;
    }
    UniformSetting u{.name = name, .values = {}, .integral = true, .where = location(n)};
    bool any_bool = false;
    collect(n, name, u, any_bool);
    if (any_bool && !u.integral)
        fail(n, fmt::format("uniform '{}' mixes booleans and fractional numbers", name));
    out.emplace_back(n.source().begin, std::move(u));
}

}  // namespace

void read_uniforms(const toml::node& n, const std::string& what, std::vector<UniformSetting>& out) {
    const toml::table& t = table(n, what);
    Placed placed;
    for (auto&& [k, v] : t) {
        std::string_view name = k.str();
        if (name.empty()) fail(k.source(), fmt::format("[{}]: a uniform name must not be empty", what));
        if (reserved(name))
            fail(k.source(), fmt::format("[{}]: '{}' is a built-in uniform; it comes from the GL state "
                                         "([camera], [lights], [material], ...)", what, name));
        flatten(v, std::string(name), placed);
    }
    // toml++ keeps keys sorted; GL applies glUniform calls in order, so that
    // "arr[2]" after "arr" overrides one element, as the file reads.
    std::stable_sort(placed.begin(), placed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [pos, u] : placed) out.push_back(std::move(u));
}

VertexAttrib read_attribute(const toml::node& n, const std::string& name, const std::string& what,
                            uint32_t vertex_count) {
    const toml::array& values = array(n, what);
    if (values.size() != vertex_count)
        fail(n, fmt::format("attribute '{}' has {} values; the mesh has {} vertices", name, values.size(),
                            vertex_count));
    VertexAttrib attrib{.name = name, .components = 1, .data = {}};
    for (size_t i = 0; i < values.size(); ++i) {
        std::string element = fmt::format("{}[{}]", what, i);
        std::vector<double> v = values[i].is_array() ? numbers(values[i], element, 1, 4)
                                                     : std::vector<double>{number(values[i], element)};
        if (i == 0) attrib.components = uint32_t(v.size());
        if (v.size() != attrib.components)
            fail(values[i], fmt::format("'{}' has {} components; element 0 has {}", element, v.size(),
                                        attrib.components));
        for (double x : v) attrib.data.push_back(float(x));
    }
    return attrib;
}

std::vector<VertexAttrib> read_attributes(const toml::node& n, const std::string& what,
                                          uint32_t vertex_count) {
    const toml::table& t = table(n, what);
    std::vector<VertexAttrib> out;
    for (auto&& [k, v] : t) {
        std::string name(k.str());
        if (!is_identifier(name))
            fail(k.source(), fmt::format("[{}]: '{}' is not a GLSL attribute name", what, name));
        if (reserved(name))
            fail(k.source(),
                 fmt::format("[{}]: '{}' is a built-in attribute; the mesh provides it", what, name));
        out.push_back(read_attribute(v, name, fmt::format("{}.{}", what, name), vertex_count));
    }
    return out;
}

}  // namespace glslrun::scene::detail
