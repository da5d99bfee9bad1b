// OBJ files through tinyobjloader (Debian's libtinyobjloader-dev is a compiled
// library, so no TINYOBJLOADER_IMPLEMENTATION here).
//
// tinyobjloader is lenient: it reads a non-number as 0, keeps out-of-range
// indices, and its polygon triangulation reads vertex positions through the
// file's indices. So the text is checked first, line by line, with the line
// number in every message; tinyobjloader then only ever sees well-formed
// statements. Polygons are split here as a fan from their first corner (what
// GL_POLYGON does), which is right for the convex polygons OBJ exporters write.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>
#include <glm/glm.hpp>
#include <tiny_obj_loader.h>

#include "glslrun/scene/meshes.h"
#include "scene/text_file.h"

namespace glslrun::scene {

namespace {

// tinyobjloader stores a face's corner count in an unsigned char.
constexpr size_t kMaxFaceCorners = 255;

// How many v, vt and vn statements precede the current line: OBJ indices
// (1-based, or negative = relative to the end) refer only to those.
struct Counts {
    int64_t v = 0, vt = 0, vn = 0;
};

using Problem = std::optional<std::string>;  // what is wrong with a line

std::string shown(std::string_view token) {
    constexpr size_t kMax = 24;
    return token.size() <= kMax ? std::string(token) : std::string(token.substr(0, kMax)) + "...";
}

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

bool is_keyword(std::string_view word) {
    auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (word.empty() || !alpha(word[0])) return false;
    for (char c : word)
        if (!alpha(c) && !(c >= '0' && c <= '9')) return false;
    return true;
}

// A finite number that fits a float (tinyobjloader stores floats).
Problem check_number(std::string_view word) {
    std::string_view digits = word;
    if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
    double value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc{} || end != digits.data() + digits.size() || !std::isfinite(value))
        return fmt::format("'{}' is not a number", shown(word));
    if (std::fabs(value) > double(std::numeric_limits<float>::max()))
        return fmt::format("{} is too large for a float", shown(word));
    return std::nullopt;
}

Problem check_numbers(const std::vector<std::string_view>& words, size_t min, size_t max) {
    const size_t count = words.size() - 1;
    if (count < min || count > max)
        return min == max ? fmt::format("'{}' needs {} numbers, got {}", words[0], min, count)
                          : fmt::format("'{}' needs {} to {} numbers, got {}", words[0], min, max, count);
    for (size_t i = 1; i < words.size(); ++i)
        if (Problem p = check_number(words[i])) return p;
    return std::nullopt;
}

// One index of a corner: nonzero, and within the `count` elements defined so far.
Problem check_index(std::string_view text, int64_t count, const char* what) {
    if (text.empty()) return fmt::format("missing {} index", what);
    std::string_view digits = text;
    if (digits[0] == '+') digits.remove_prefix(1);
    int64_t index = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    if (ec == std::errc::result_out_of_range)
        return fmt::format("{} index {} is out of range", what, shown(text));
    if (ec != std::errc{} || end != digits.data() + digits.size())
        return fmt::format("'{}' is not a {} index", shown(text), what);
    if (index == 0) return fmt::format("{} index 0 (OBJ indices start at 1)", what);
    if (index > count || index < -count)
        return fmt::format("{} index {} is out of range: {} defined before this line", what, index,
                           count == 0 ? std::string("none") : fmt::format("only {}", count));
    return std::nullopt;
}

// "v", "v/t", "v//n" or "v/t/n".
Problem check_corner(std::string_view corner, const Counts& counts) {
    std::vector<std::string_view> parts;
    size_t start = 0;
    for (size_t slash; (slash = corner.find('/', start)) != std::string_view::npos; start = slash + 1)
        parts.push_back(corner.substr(start, slash - start));
    parts.push_back(corner.substr(start));
    if (parts.size() > 3) return fmt::format("'{}' is not a corner (v, v/t, v//n or v/t/n)", shown(corner));
    if (Problem p = check_index(parts[0], counts.v, "vertex")) return p;
    if (parts.size() == 3 && parts[1].empty()) return check_index(parts[2], counts.vn, "normal");
    if (parts.size() >= 2)
        if (Problem p = check_index(parts[1], counts.vt, "texture coordinate")) return p;
    if (parts.size() == 3) return check_index(parts[2], counts.vn, "normal");
    return std::nullopt;
}

Problem check_corners(const std::vector<std::string_view>& words, size_t min, const Counts& counts) {
    const size_t corners = words.size() - 1;
    if (corners < min) return fmt::format("'{}' needs at least {} vertices, got {}", words[0], min, corners);
    if (words[0] == "f" && corners > kMaxFaceCorners)
        return fmt::format("a face with {} vertices (at most {} are supported)", corners, kMaxFaceCorners);
    for (size_t i = 1; i < words.size(); ++i)
        if (Problem p = check_corner(words[i], counts)) return p;
    return std::nullopt;
}

// Checks one line and counts what it defines. Statements that do not make
// geometry (o, g, s, usemtl, mtllib, curves, ...) pass unchecked.
Problem check_line(std::string_view line, Counts& counts) {
    for (size_t i = 0; i < line.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(line[i]);
        if ((c < 0x20 && c != '\t') || c == 0x7f)
            return fmt::format("byte 0x{:02x} in column {}: not an OBJ text file", c, i + 1);
    }
    const std::vector<std::string_view> words = split_words(line);
    if (words.empty() || words[0][0] == '#') return std::nullopt;
    const std::string_view key = words[0];
    if (!is_keyword(key)) return fmt::format("'{}' is not an OBJ statement", shown(key));
    if (key == "v" || key == "vt" || key == "vn") {
        const bool texcoord = key == "vt";
        if (Problem p = check_numbers(words, texcoord ? 1 : 3, key == "v" ? 7 : 3)) return p;
        ++(key == "v" ? counts.v : texcoord ? counts.vt : counts.vn);
        return std::nullopt;
    }
    if (key == "f") return check_corners(words, 3, counts);
    if (key == "l") return check_corners(words, 2, counts);
    if (key == "p") return check_corners(words, 1, counts);
    return std::nullopt;
}

// Lines end at "\n", "\r\n" or a lone "\r", as tinyobjloader reads them.
std::optional<Error> check_obj_text(std::string_view text, const std::string& path) {
    Counts counts;
    int line_number = 0;
    size_t pos = 0;
    while (pos < text.size()) {
        ++line_number;
        size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos) end = text.size();
        if (Problem p = check_line(text.substr(pos, end - pos), counts)) return Error(*p, path, line_number);
        pos = end;
        if (pos == text.size()) break;
        const bool carriage_return = text[pos++] == '\r';
        if (carriage_return && pos < text.size() && text[pos] == '\n') ++pos;
    }
    return std::nullopt;
}

// tinyobjloader's messages sometimes say "line N"; keep N for the Error.
Error parser_error(const std::string& message, const std::string& path) {
    int line = 0;
    const size_t at = message.find("line ");
    if (at != std::string::npos) line = std::atoi(message.c_str() + at + 5);
    std::string first = message.substr(0, message.find('\n'));
    return Error(fmt::format("OBJ file not understood: {}", first.empty() ? "unknown error" : first), path, line);
}

// A vertex of the mesh: one distinct (position, texcoord, normal) corner.
// Corners without a file normal get the face's flat normal, so they are keyed
// by the face instead (`normal` = -2 - face).
struct CornerKey {
    int64_t position, texcoord, normal;
    bool operator==(const CornerKey&) const = default;
};

struct CornerHash {
    size_t operator()(const CornerKey& k) const {
        const std::hash<int64_t> h;
        return h(k.position) ^ (h(k.texcoord) * 0x9e3779b97f4a7c15ULL) ^ (h(k.normal) * 0xc2b2ae3d27d4eb4fULL);
    }
};

class MeshAssembler {
public:
    explicit MeshAssembler(const tinyobj::attrib_t& attrib) : attrib_(attrib) {}

    // Adds one polygon (its corners); false when an index is out of range.
    bool add_face(const tinyobj::index_t* corners, size_t count) {
        for (size_t k = 0; k < count; ++k)
            if (!in_range(corners[k])) return false;
        const glm::vec3 flat = flat_normal(corners, count);
        std::vector<uint32_t> ids;
        for (size_t k = 0; k < count; ++k) ids.push_back(vertex(corners[k], flat));
        for (size_t k = 1; k + 1 < count; ++k) indices_.insert(indices_.end(), {ids[0], ids[k], ids[k + 1]});
        ++faces_;
        return true;
    }

    Mesh finish() {
        Mesh mesh;
        mesh.primitive = Primitive::Triangles;
        mesh.vertex_count = uint32_t(pos_.size() / 3);
        mesh.attribs = {{"gl_Vertex", 3, std::move(pos_)},
                        {"gl_Normal", 3, std::move(nrm_)},
                        {"gl_MultiTexCoord0", 2, std::move(tex_)}};
        mesh.indices = std::move(indices_);
        return mesh;
    }

private:
    static bool index_ok(int index, size_t values, size_t per_element, bool optional) {
        if (index < 0) return optional && index == -1;
        return size_t(index) < values / per_element;
    }
    bool in_range(const tinyobj::index_t& c) const {
        return index_ok(c.vertex_index, attrib_.vertices.size(), 3, false) &&
               index_ok(c.texcoord_index, attrib_.texcoords.size(), 2, true) &&
               index_ok(c.normal_index, attrib_.normals.size(), 3, true);
    }
    glm::vec3 position(int index) const {
        const tinyobj::real_t* p = &attrib_.vertices[size_t(index) * 3];
        return {float(p[0]), float(p[1]), float(p[2])};
    }
    // Newell's method: the polygon's area-weighted normal, counter-clockwise
    // = towards the viewer. A face of zero area draws nothing; +z stands in.
    glm::vec3 flat_normal(const tinyobj::index_t* corners, size_t count) const {
        glm::dvec3 n(0.0);
        for (size_t k = 0; k < count; ++k) {
            const glm::dvec3 a = position(corners[k].vertex_index);
            const glm::dvec3 b = position(corners[(k + 1) % count].vertex_index);
            n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        }
        const double length = glm::length(n);
        return length > 0 && std::isfinite(length) ? glm::vec3(n / length) : glm::vec3(0, 0, 1);
    }
    uint32_t vertex(const tinyobj::index_t& c, const glm::vec3& flat) {
        const CornerKey key{c.vertex_index, c.texcoord_index, c.normal_index >= 0 ? c.normal_index : -2 - faces_};
        const auto [it, added] = ids_.try_emplace(key, uint32_t(pos_.size() / 3));
        if (!added) return it->second;
        const glm::vec3 p = position(c.vertex_index);
        pos_.insert(pos_.end(), {p.x, p.y, p.z});
        if (c.normal_index >= 0) {
            const tinyobj::real_t* n = &attrib_.normals[size_t(c.normal_index) * 3];
            nrm_.insert(nrm_.end(), {float(n[0]), float(n[1]), float(n[2])});
        } else {
            nrm_.insert(nrm_.end(), {flat.x, flat.y, flat.z});
        }
        if (c.texcoord_index >= 0) {
            const tinyobj::real_t* t = &attrib_.texcoords[size_t(c.texcoord_index) * 2];
            tex_.insert(tex_.end(), {float(t[0]), float(t[1])});
        } else {
            tex_.insert(tex_.end(), {0.0f, 0.0f});
        }
        return it->second;
    }

    const tinyobj::attrib_t& attrib_;
    std::unordered_map<CornerKey, uint32_t, CornerHash> ids_;
    std::vector<float> pos_, nrm_, tex_;
    std::vector<uint32_t> indices_;
    int64_t faces_ = 0;
};

}  // namespace

Result<Mesh> load_obj(const std::string& path) {
    Result<std::string> text = read_text_file(path, "OBJ file");
    if (!text) return text.error();
    if (std::optional<Error> e = check_obj_text(*text, path)) return *e;

    tinyobj::ObjReaderConfig config;
    config.triangulate = false;   // fan-split below; see the top of the file
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // From the string, so that no .mtl file is opened: materials are not used.
    if (!reader.ParseFromString(*text, "", config)) return parser_error(reader.Error(), path);

    MeshAssembler mesh(reader.GetAttrib());
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        size_t offset = 0;
        for (const size_t corners : shape.mesh.num_face_vertices) {
            if (offset + corners > shape.mesh.indices.size() ||
                !mesh.add_face(&shape.mesh.indices[offset], corners))
                return Error("OBJ file has a face index out of range", path);
            offset += corners;
        }
    }
    Mesh result = mesh.finish();
    if (result.indices.empty()) return Error("OBJ file has no faces: nothing to draw", path);
    return result;
}

}  // namespace glslrun::scene
