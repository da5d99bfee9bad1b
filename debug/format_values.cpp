// Values as GLSL writes them: "vec3(1, 0, 0.25)", matrices by columns.
#include <fmt/format.h>

#include "debug/trace.h"

namespace glslrun::debug {

std::string type_name(const ir::ValueType& t) {
    if (t.is_sampler) return "sampler";
    const char* prefix = t.kind == ir::Kind::F32 ? "" : t.kind == ir::Kind::I32 ? "i" : "b";
    if (t.cols > 1) return t.cols == t.rows ? fmt::format("mat{}", t.cols) : fmt::format("mat{}x{}", t.cols, t.rows);
    if (t.rows > 1) return fmt::format("{}vec{}", prefix, t.rows);
    return t.kind == ir::Kind::F32 ? "float" : t.kind == ir::Kind::I32 ? "int" : "bool";
}

std::string binding_type(const ir::Binding& b) { return type_name(ir::ValueType{b.kind, 1, uint8_t(b.count), false}); }

// Columns and rows of a "matN" / "matCxR" type; {1, n} otherwise.
std::pair<int, int> matrix_shape(const std::string& type, size_t count) {
    int cols = 0, rows = 0;
    if (std::sscanf(type.c_str(), "mat%dx%d", &cols, &rows) == 2 && cols * rows > 0) return {cols, rows};
    if (std::sscanf(type.c_str(), "mat%d", &cols) == 1 && cols > 0) return {cols, cols};
    return {1, int(count)};
}

namespace {

std::string scalar(const Values& v, double x) {
    switch (v.kind) {
        case ir::Kind::F32:
            return v.wide ? fmt::format("{}", x) : fmt::format("{}", float(x));
        case ir::Kind::I32:
            return fmt::format("{}", int64_t(x));
        case ir::Kind::Bool:
            return x != 0 ? "true" : "false";
    }
    return "?";
}

std::string vector_text(const Values& v, size_t from, size_t n) {
    std::string out;
    for (size_t i = from; i < from + n && i < v.c.size(); ++i) out += (i > from ? ", " : "") + scalar(v, v.c[i]);
    if (n == 1) return out;
    const char* prefix = v.kind == ir::Kind::F32 ? "" : v.kind == ir::Kind::I32 ? "i" : "b";
    return n <= 4 ? fmt::format("{}vec{}({})", prefix, n, out) : "{" + out + "}";
}

}  // namespace

std::string format_value(const Values& v, const std::string& type) {
    auto [cols, rows] = matrix_shape(type, v.c.size());
    if (cols == 1) return vector_text(v, 0, v.c.size());
    size_t per_matrix = size_t(cols) * size_t(rows);
    std::string out;
    for (size_t m = 0; m < v.c.size(); m += per_matrix) {  // arrays of matrices: one after another
        std::string columns;
        for (int c = 0; c < cols; ++c)
            columns += (c ? ", " : "") + vector_text(v, m + size_t(c) * size_t(rows), size_t(rows));
        out += (m ? ", " : "") + fmt::format("{}({})", type.substr(0, type.find('[')), columns);
    }
    return out;
}

std::vector<std::string> format_matrix_rows(const Values& v, const std::string& type) {
    auto [cols, rows] = matrix_shape(type, v.c.size());
    if (cols == 1) return {format_value(v, type)};
    std::vector<std::string> lines;
    size_t per_matrix = size_t(cols) * size_t(rows);
    for (size_t m = 0; m < v.c.size(); m += per_matrix)
        for (int r = 0; r < rows; ++r) {
            std::string line = "| ";
            for (int c = 0; c < cols; ++c) {
                size_t i = m + size_t(c) * size_t(rows) + size_t(r);
                line += fmt::format("{:>10} ", i < v.c.size() ? scalar(v, v.c[i]) : "");
            }
            lines.push_back(line + "|");
        }
    return lines;
}

}  // namespace glslrun::debug
