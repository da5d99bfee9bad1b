// Typed readers over toml++ nodes: every value of a scene file passes one of
// these, so type, length, finiteness and range checks live in one place.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "scene/scene_reader.h"

namespace glslrun::scene::detail {

void fail(const toml::source_region& where, std::string message) {
    std::string file = where.path ? *where.path : std::string();
    throw SceneFailure{Error(std::move(message), std::move(file), int(where.begin.line))};
}

void fail(const toml::node& at, std::string message) { fail(at.source(), std::move(message)); }

SourceLoc location(const toml::node& n) {
    const toml::source_region& r = n.source();
    return SourceLoc{r.path ? *r.path : std::string(), int(r.begin.line)};
}

namespace {

// Messages quote a string value; a pasted paragraph need not be repeated.
std::string shortened(std::string_view s) {
    return s.size() <= 40 ? std::string(s) : std::string(s.substr(0, 37)) + "...";
}

}  // namespace

std::string describe(const toml::node& n) {
    switch (n.type()) {
        case toml::node_type::table: return "a table";
        case toml::node_type::array: return fmt::format("an array of {} values", n.as_array()->size());
        case toml::node_type::string:
            return fmt::format("the string \"{}\"", shortened(n.as_string()->get()));
        case toml::node_type::integer: return fmt::format("the integer {}", n.as_integer()->get());
        case toml::node_type::floating_point:
            return fmt::format("the number {}", n.as_floating_point()->get());
        case toml::node_type::boolean: return n.as_boolean()->get() ? "true" : "false";
        default: return "a date or time";
    }
}

namespace {

char lower(char c) { return char(std::tolower(static_cast<unsigned char>(c))); }

// Optimal string alignment distance, case-insensitive: a transposition
// ("ambeint") is one edit, as a typist would count it. Three rolling rows (a
// transposition looks two rows back).
size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<size_t> before(b.size() + 1), previous(b.size() + 1), row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        std::swap(before, previous);
        std::swap(previous, row);
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
                row[j] = std::min(row[j], before[j - 2] + 1);
        }
    }
    return row[b.size()];
}

std::string range_text(const Range& r) {
    if (r.hi >= FLT_MAX) return fmt::format("{} {}", r.lo_open ? ">" : ">=", r.lo);
    return fmt::format("in {}{}, {}{}", r.lo_open ? '(' : '[', r.lo, r.hi, r.hi_open ? ')' : ']');
}

std::string count_text(size_t min, size_t max) {
    if (min == max) return fmt::format("{}", min);
    if (max == min + 1) return fmt::format("{} or {}", min, max);
    return fmt::format("{} to {}", min, max);
}

}  // namespace

std::string closest(std::string_view word, const std::vector<std::string_view>& candidates) {
    if (word.size() > 64) return {};  // no key is that long; spare the quadratic distance
    std::string_view best;
    size_t best_distance = std::numeric_limits<size_t>::max();
    for (std::string_view c : candidates) {
        size_t d = edit_distance(word, c);
        if (d < best_distance) best_distance = d, best = c;
    }
    // A third of the word may be wrong: "difuse" -> "diffuse", never "xyz" -> "fog".
    size_t allowed = std::max<size_t>(2, word.size() / 3);
    return best_distance <= allowed ? std::string(best) : std::string();
}

std::string suggestion(std::string_view word, const std::vector<std::string_view>& candidates,
                       std::string_view noun) {
    std::string best = closest(word, candidates);
    if (!best.empty()) return fmt::format("did you mean '{}'?", best);
    return fmt::format("valid {}: {}", noun, fmt::join(candidates, ", "));
}

void check_range(const toml::node& at, const std::string& what, double v, const Range& r) {
    bool below = r.lo_open ? v <= r.lo : v < r.lo;
    bool above = r.hi_open ? v >= r.hi : v > r.hi;
    if (!below && !above) return;
    std::string why = r.why ? fmt::format(" ({})", r.why) : std::string();
    fail(at, fmt::format("'{}' must be {}{}; got {}", what, range_text(r), why, v));
}

double number(const toml::node& n, const std::string& what) {
    double v = 0;
    if (auto i = n.as_integer()) v = double(i->get());
    else if (auto f = n.as_floating_point()) v = f->get();
    else fail(n, fmt::format("'{}' must be a number (got {})", what, describe(n)));
    if (!std::isfinite(v)) fail(n, fmt::format("'{}' must be a finite number (got {})", what, v));
    if (std::abs(v) > FLT_MAX) fail(n, fmt::format("'{}' = {} does not fit in a float", what, v));
    return v;
}

int64_t integer(const toml::node& n, const std::string& what, int64_t lo, int64_t hi) {
    auto i = n.as_integer();
    if (!i) fail(n, fmt::format("'{}' must be an integer (got {})", what, describe(n)));
    int64_t v = i->get();
    if (v < lo || v > hi) fail(n, fmt::format("'{}' must be in [{}, {}]; got {}", what, lo, hi, v));
    return v;
}

bool boolean(const toml::node& n, const std::string& what) {
    auto b = n.as_boolean();
    if (!b) fail(n, fmt::format("'{}' must be true or false (got {})", what, describe(n)));
    return b->get();
}

const toml::table& table(const toml::node& n, const std::string& what) {
    auto t = n.as_table();
    if (!t) fail(n, fmt::format("'{}' must be a table (got {})", what, describe(n)));
    return *t;
}

const toml::array& array(const toml::node& n, const std::string& what) {
    auto a = n.as_array();
    if (!a) fail(n, fmt::format("'{}' must be an array (got {})", what, describe(n)));
    return *a;
}

std::vector<double> numbers(const toml::node& n, const std::string& what, size_t min, size_t max) {
    auto a = n.as_array();
    if (!a || a->size() < min || a->size() > max)
        fail(n, fmt::format("'{}' must be an array of {} numbers (got {})", what, count_text(min, max),
                            describe(n)));
    std::vector<double> out;
    for (size_t i = 0; i < a->size(); ++i) out.push_back(number((*a)[i], fmt::format("{}[{}]", what, i)));
    return out;
}

glm::dvec4 color(const toml::node& n, const std::string& what) {
    std::vector<double> v = numbers(n, what, 3, 4);
    return {v[0], v[1], v[2], v.size() == 4 ? v[3] : 1.0};
}

glm::dmat4 matrix(const toml::node& n, const std::string& what) {
    auto a = n.as_array();
    std::vector<double> flat;
    if (a && a->size() == 4 && (*a)[0].is_array()) {
        for (size_t c = 0; c < 4; ++c) {
            std::vector<double> col = numbers((*a)[c], fmt::format("{}[{}]", what, c), 4, 4);
            flat.insert(flat.end(), col.begin(), col.end());
        }
    } else if (a && a->size() == 16) {
        flat = numbers(n, what, 16, 16);
    } else {
        fail(n, fmt::format("'{}' must be a matrix: 16 numbers in column-major order (as "
                            "glLoadMatrixf takes them) or 4 columns of 4 (got {})", what, describe(n)));
    }
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = flat[size_t(c * 4 + r)];
    return m;
}

size_t choice(const toml::node& n, const std::string& what, const std::vector<std::string_view>& options) {
    auto s = n.as_string();
    if (!s)
        fail(n, fmt::format("'{}' must be one of \"{}\" (got {})", what, fmt::join(options, "\", \""),
                            describe(n)));
    std::string_view v = s->get();
    for (size_t i = 0; i < options.size(); ++i)
        if (options[i] == v) return i;
    fail(n, fmt::format("'{}' = \"{}\" is not allowed; {}", what, v, suggestion(v, options, "values")));
}

int index_key(const toml::key& k, int count, const std::string& what, std::string_view limit_message) {
    std::string_view s = k.str();
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    bool digits = !s.empty() && s.size() <= 3 && std::all_of(s.begin(), s.end(), digit);
    int i = digits ? std::stoi(std::string(s)) : -1;
    // "00" would be a second name for light 0, silently merged with "0".
    if (!digits || i >= count || s != std::to_string(i))
        fail(k.source(), fmt::format("'{}.{}': {}", what, s, limit_message));
    return i;
}

// ----------------------------------------------------------------- Section ---

void Section::allow(const std::vector<std::string_view>& keys) const {
    const toml::key* first_bad = nullptr;
    for (auto&& [k, v] : table_) {
        if (std::find(keys.begin(), keys.end(), k.str()) != keys.end()) continue;
        // Report the earliest line: toml++ iterates keys sorted, not in file order.
        if (!first_bad || k.source().begin.line < first_bad->source().begin.line) first_bad = &k;
    }
    if (!first_bad) return;
    std::string where = path_.empty() ? std::string("at the top level") : fmt::format("in [{}]", path_);
    fail(first_bad->source(), fmt::format("unknown key '{}' {}; {}", first_bad->str(), where,
                                          suggestion(first_bad->str(), keys)));
}

const toml::node& Section::require(std::string_view key, std::string_view why) const {
    if (const toml::node* n = get(key)) return *n;
    fail(table_, fmt::format("[{}] needs '{}' ({})", path_, key, why));
}

std::string Section::name(std::string_view key) const {
    return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

bool Section::read(std::string_view key, bool& out) const {
    const toml::node* n = get(key);
    if (n) out = boolean(*n, name(key));
    return n != nullptr;
}

bool Section::read(std::string_view key, float& out, const Range& r) const {
    const toml::node* n = get(key);
    if (!n) return false;
    double v = number(*n, name(key));
    check_range(*n, name(key), v, r);
    out = float(v);
    return true;
}

bool Section::read_color(std::string_view key, glm::vec4& out) const {
    const toml::node* n = get(key);
    if (n) out = glm::vec4(color(*n, name(key)));
    return n != nullptr;
}

bool Section::read_vec(std::string_view key, glm::vec3& out) const {
    const toml::node* n = get(key);
    if (!n) return false;
    std::vector<double> v = numbers(*n, name(key), 3, 3);
    out = glm::vec3(float(v[0]), float(v[1]), float(v[2]));
    return true;
}

bool Section::read_vec(std::string_view key, glm::vec4& out) const {
    const toml::node* n = get(key);
    if (!n) return false;
    std::vector<double> v = numbers(*n, name(key), 4, 4);
    out = glm::vec4(float(v[0]), float(v[1]), float(v[2]), float(v[3]));
    return true;
}

}  // namespace glslrun::scene::detail
