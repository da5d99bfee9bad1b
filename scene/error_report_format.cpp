// The error report's output: its images, the table for people and the
// `key value` lines for scripts.
#include <filesystem>

#include <fmt/format.h>

#include "glslrun/scene/error_report.h"

namespace glslrun::scene {

namespace {

constexpr const char* kChannelNames[] = {"r", "g", "b", "a"};

// "gl_FragData[0]" -> "gl_FragData_0": a file name without brackets.
std::string file_stem(const std::string& name) {
    std::string out;
    for (char c : name)
        if (c != ']') out += c == '[' ? '_' : c;
    return out;
}

std::string ulp_text(uint64_t ulp) { return ulp == kNanUlp ? "NaN" : std::to_string(ulp); }

std::string values_text(const std::vector<float>& values) {
    std::string out;
    for (float v : values) out += fmt::format("{}{:.9g}", out.empty() ? "" : ", ", v);
    return "(" + out + ")";
}

std::string channel_row(const std::string& output, const std::string& channel, const ChannelError& e,
                        bool quantized) {
    std::string row = fmt::format("{:<16} {:<7} {:>10} {:>12.4g} {:>12.4g}", output, channel, ulp_text(e.max_ulp),
                                  e.mean_ulp(), e.max_abs);
    if (quantized) row += fmt::format(" {:>9} {:>11.4g}", e.max_8bit, e.mean_8bit());
    if (e.nan_mismatches) row += fmt::format("   ({} NaN in one only)", e.nan_mismatches);
    return row + "\n";
}

std::string worst_line(const char* what, const WorstPlace& w, const ErrorReport& r) {
    if (!w.found || (w.ulp == 0 && w.diff_8bit == 0)) return fmt::format("  worst pixel {}: none, no pixel differs\n", what);
    return fmt::format("  worst pixel {}: x {} y {} (top-left origin): reference {}, {} {}, {} ULP{}\n", what, w.x,
                       w.y, values_text(w.reference), precision_name(r.mode), values_text(w.actual),
                       w.ulp == kCoverageMismatch ? "-" : ulp_text(w.ulp),
                       w.reference.size() == 4 ? fmt::format(", {} in 8 bits", w.diff_8bit) : "");
}

std::string image_section(const ImageError& e, const ErrorReport& r) {
    std::string out;
    if (e.channels > 1)
        for (int c = 0; c < e.channels; ++c)
            out += channel_row(c == 0 ? e.name : "", kChannelNames[c], e.channel[size_t(c)], e.quantized);
    out += channel_row(e.channels > 1 ? "" : e.name, "all", e.total(), e.quantized);
    uint64_t covered = e.covered_both + e.covered_one;
    out += fmt::format("  pixels: {} covered in both images, {} in one only", e.covered_both, e.covered_one);
    if (e.quantized)
        out += fmt::format("; {} differ in 8 bits ({:.3f}% of those covered)", e.differing_8bit,
                           covered ? 100.0 * double(e.differing_8bit) / double(covered) : 0.0);
    out += "\n" + worst_line("by ULP", e.worst_ulp, r);
    if (e.quantized) out += worst_line("in 8 bits", e.worst_8bit, r);
    return out;
}

std::string vertex_section(const ErrorReport& r) {
    if (r.varyings.empty()) return "";
    std::string out = fmt::format("\nvertex outputs (every vertex of every object, all components)\n"
                                  "{:<20} {:>5} {:>10} {:>12} {:>12}   worst: object, vertex\n",
                                  "output", "comps", "max ULP", "mean ULP", "max abs");
    for (const VaryingError& v : r.varyings) {
        out += fmt::format("{:<20} {:>5} {:>10} {:>12.4g} {:>12.4g}", v.name, v.components, ulp_text(v.error.max_ulp),
                           v.error.mean_ulp(), v.error.max_abs);
        if (v.worst.found && v.worst.ulp > 0)
            out += fmt::format("   {}, {}: reference {}, {} {}", v.worst.y, v.worst.x, values_text(v.worst.reference),
                               precision_name(r.mode), values_text(v.worst.actual));
        out += "\n";
    }
    return out;
}

std::string ablation_section(const ErrorReport& r) {
    if (r.ablation.empty()) return "";
    std::string out = fmt::format(
        "\nwhere fast's error comes from: the colour with one class of approximations, every other op precise\n"
        "{:<12} {:>10} {:>12} {:>9} {:>11} {:>12}   worst pixel in 8 bits\n", "fast ops", "max ULP",
        "mean ULP", "max 8-bit", "pixels off", "edge moved");
    for (const AblationRow& a : r.ablation) {
        out += fmt::format("{:<12} {:>10} {:>12.4g} {:>9} {:>11} {:>12}", a.ops, ulp_text(a.color.max_ulp),
                           a.color.mean_ulp(), a.color.max_8bit, a.differing_8bit, a.covered_one);
        if (a.worst_8bit.found && a.worst_8bit.diff_8bit > 0) out += fmt::format("   x {} y {}", a.worst_8bit.x, a.worst_8bit.y);
        out += "\n";
    }
    return out + "(none: precise; all: fast; inversesqrt includes normalize and x / sqrt(y). \"edge moved\": "
                 "pixels covered in one image only)\n";
}

void key(std::string& out, const std::string& name, const std::string& value) {
    out += fmt::format("{:<36} {}\n", name, value);
}

void channel_keys(std::string& out, const std::string& prefix, const ChannelError& e, bool quantized) {
    key(out, prefix + ".max_ulp", std::to_string(e.max_ulp));
    key(out, prefix + ".mean_ulp", fmt::format("{:.6g}", e.mean_ulp()));
    key(out, prefix + ".max_abs", fmt::format("{:.6g}", e.max_abs));
    key(out, prefix + ".nan_mismatches", std::to_string(e.nan_mismatches));
    if (!quantized) return;
    key(out, prefix + ".max_8bit", std::to_string(e.max_8bit));
    key(out, prefix + ".mean_8bit", fmt::format("{:.6g}", e.mean_8bit()));
}

void image_keys(std::string& out, const ImageError& e) {
    std::string p = "frag." + e.name;
    channel_keys(out, p, e.total(), e.quantized);
    if (e.channels > 1)
        for (int c = 0; c < e.channels; ++c) channel_keys(out, p + "." + kChannelNames[c], e.channel[size_t(c)], e.quantized);
    key(out, p + ".covered_both", std::to_string(e.covered_both));
    key(out, p + ".covered_one", std::to_string(e.covered_one));
    if (e.quantized) key(out, p + ".differing_pixels", std::to_string(e.differing_8bit));
    // "none" where no pixel differs, so that scripts do not chase a pixel without an error.
    auto place = [](const WorstPlace& w, bool differs) {
        return differs ? fmt::format("{} {}", w.x, w.y) : std::string("none");
    };
    key(out, p + ".worst_ulp_xy", place(e.worst_ulp, e.worst_ulp.found && e.worst_ulp.ulp > 0));
    if (e.quantized) key(out, p + ".worst_8bit_xy", place(e.worst_8bit, e.worst_8bit.found && e.worst_8bit.diff_8bit > 0));
}

}  // namespace

Result<std::vector<std::string>> write_error_images(const ErrorReport& r, const std::string& dir,
                                                    const std::function<Status(const std::string&)>& check_path) {
    namespace fs = std::filesystem;
    std::vector<std::string> written;
    auto write = [&](const Image& image, const std::string& name) -> Status {
        std::string path = (fs::path(dir) / name).string();
        if (check_path)
            if (Status st = check_path(path); !st) return st;
        if (Status st = write_png(image, path); !st) return st;
        written.push_back(path);
        return Ok{};
    };
    if (Status st = write(r.reference_image, "reference.png"); !st) return st.error();
    if (Status st = write(r.mode_image, fmt::format("actual-{}.png", precision_name(r.mode))); !st) return st.error();
    if (!r.outputs.empty())
        if (Status st = write(heat_map_legend_image(), "heat_legend.png"); !st) return st.error();
    for (const ImageError& e : r.outputs) {
        if (Status st = write(heat_map(e), file_stem(e.name) + "_ulp.png"); !st) return st.error();
        if (!e.quantized) continue;
        auto diff = diff_image(r.reference_image, r.mode_image, 0);
        if (!diff) return diff.error();
        if (Status st = write(*diff, file_stem(e.name) + "_diff8.png"); !st) return st.error();
    }
    return written;
}

std::string format_error_table(const ErrorReport& r, const std::vector<std::string>& files) {
    std::string out = fmt::format("error report: {} against reference\nscene    {} ({}x{})\n"
                                  "time     reference {:.1f} ms, {} {:.1f} ms (one frame each)\n\n",
                                  precision_name(r.mode), r.scene, r.width, r.height, r.reference_ms,
                                  precision_name(r.mode), r.mode_ms);
    out += fmt::format("fragment outputs (ULP over pixels covered in both images, 8-bit over pixels covered in either)\n"
                       "{:<16} {:<7} {:>10} {:>12} {:>12} {:>9} {:>11}\n",
                       "output", "channel", "max ULP", "mean ULP", "max abs", "max 8-bit", "mean 8-bit");
    for (const ImageError& e : r.outputs) out += image_section(e, r);
    out += vertex_section(r);
    out += ablation_section(r);
    for (const std::string& note : r.notes) out += "note: " + note + "\n";
    if (!files.empty()) {
        out += "\nfiles:";
        for (const std::string& f : files) out += " " + f;
        out += "\nheat maps (*_ulp.png, their legend in heat_legend.png): " + heat_map_legend() + "\n";
        out += "8-bit differences (*_diff8.png): the reference dimmed, pixels that differ in red\n";
    }
    return out;
}

std::string format_error_keys(const ErrorReport& r) {
    std::string out;
    key(out, "mode", precision_name(r.mode));
    key(out, "scene", r.scene);
    key(out, "size", fmt::format("{}x{}", r.width, r.height));
    key(out, "reference_ms", fmt::format("{:.3f}", r.reference_ms));
    key(out, "mode_ms", fmt::format("{:.3f}", r.mode_ms));
    for (const ImageError& e : r.outputs) image_keys(out, e);
    for (const VaryingError& v : r.varyings) channel_keys(out, "vertex." + v.name, v.error, false);
    for (const AblationRow& a : r.ablation) {
        std::string p = "ablation." + a.ops;
        channel_keys(out, p, a.color, true);
        key(out, p + ".differing_pixels", std::to_string(a.differing_8bit));
        key(out, p + ".covered_one", std::to_string(a.covered_one));
    }
    return out;
}

}  // namespace glslrun::scene
