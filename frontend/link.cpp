// Cross-stage rules and the VS->FS varying map.
#include "frontend/link.h"

#include <map>

#include <fmt/format.h>

namespace glslrun::frontend {

void check_interface(const LinkInput& in, std::vector<Diagnostic>& diags) {
    if (in.vs_is_user && !in.vs->referenced.count("gl_Position"))
        diags.push_back(Diagnostic{in.vs_file, 0, "vertex shader does not write to 'gl_Position'", false});
    for (const auto& [name, var] : in.fs->interface) {
        if (!var.input || name.rfind("gl_", 0) == 0) continue;
        auto it = in.vs->interface.find(name);
        if (it == in.vs->interface.end() || it->second.input) {
            diags.push_back(Diagnostic{in.fs_file, 0,
                                       fmt::format("varying '{}' is read by the fragment shader but not written by "
                                                   "the vertex shader",
                                                   name),
                                       false});
        } else if (it->second.signature != var.signature) {
            diags.push_back(Diagnostic{in.fs_file, 0,
                                       fmt::format("varying '{}' has type {} in the vertex shader but {} in the "
                                                   "fragment shader",
                                                   name, it->second.signature, var.signature),
                                       false});
        }
    }
    for (const auto& [name, sig] : in.fs->declared_varyings) {
        auto it = in.vs->declared_varyings.find(name);
        if (it != in.vs->declared_varyings.end() && it->second != sig)
            diags.push_back(Diagnostic{in.fs_file, 0,
                                       fmt::format("varying '{}' has type {} in the vertex shader but {} in the "
                                                   "fragment shader",
                                                   name, it->second, sig),
                                       false});
    }
}

void link_varyings(ir::Program& program) {
    std::map<std::string, int> vs_out;
    for (size_t i = 0; i < program.vertex.outputs.size(); ++i) vs_out[program.vertex.outputs[i].name] = int(i);
    auto find = [&](const std::string& name) {
        auto it = vs_out.find(name);
        return it == vs_out.end() ? -1 : it->second;
    };
    for (size_t i = 0; i < program.fragment.inputs.size(); ++i) {
        const std::string& name = program.fragment.inputs[i].name;
        ir::VaryingLink link;
        link.fs_input = uint32_t(i);
        if (name == "gl_Color") {
            link.vs_output = find("gl_FrontColor");
            link.vs_back_output = find("gl_BackColor");
            link.is_color = true;
        } else if (name == "gl_SecondaryColor") {
            link.vs_output = find("gl_FrontSecondaryColor");
            link.vs_back_output = find("gl_BackSecondaryColor");
            link.is_color = true;
        } else if (name == "gl_FragCoord" || name == "gl_FrontFacing" || name == "gl_PointCoord") {
            link.vs_output = -1;
        } else {
            link.vs_output = find(name);
        }
        program.varyings.push_back(link);
    }
}

}  // namespace glslrun::frontend
