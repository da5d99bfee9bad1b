// ir/helper_lookups.cpp: whether a helper lane's texture lookups can change
// a fragment's result. Where the analysis says no, the fragment stage skips
// them, and the textured scenes' images (tools/image_hashes.sh,
// backend_identical) must stay what they were.
#include <catch2/catch.hpp>

#include "ir/passes.h"
#include "tests/frontend/helpers.h"

namespace glslrun::test {
namespace {

bool matter(const std::string& body) {
    const std::string fs = "uniform sampler2D t;\nvarying vec2 uv;\n" + body;
    const char* vs = "varying vec2 uv;\nvoid main() { uv = gl_Vertex.xy; gl_Position = ftransform(); }\n";
    ir::Program p = compile_ok(vs, fs);
    const bool before = ir::helper_lookups_matter(p.fragment);
    // optimize() records the same answer.
    REQUIRE(ir::optimize(p.fragment, ir::PassOptions{}) == "");
    CHECK(p.fragment.helper_lookups_matter == before);
    return before;
}

}  // namespace

TEST_CASE("helper lanes' lookups are unread without derivatives or branches on them", "[ir][helper_lookups]") {
    CHECK_FALSE(matter("void main() { gl_FragColor = texture2D(t, uv); }"));
    CHECK_FALSE(matter("void main() { gl_FragColor = texture2D(t, uv) * 2.0 + vec4(dFdx(uv.x)); }"));
    CHECK_FALSE(matter("void main() { gl_FragColor = vec4(fwidth(uv), 0.0, 1.0); }"));
    // A lookup whose coordinate came from a lookup, explicit bias: its
    // derivatives are of uv, not of the first lookup.
    CHECK_FALSE(matter("void main() { vec4 a = texture2D(t, uv); gl_FragColor = texture2D(t, uv * 0.5, a.r); }"));
}

TEST_CASE("helper lanes' lookups matter under a derivative or a branch", "[ir][helper_lookups]") {
    CHECK(matter("void main() { gl_FragColor = vec4(dFdx(texture2D(t, uv).r)); }"));
    CHECK(matter("void main() { gl_FragColor = vec4(fwidth(texture2D(t, uv).g * 3.0)); }"));
    // A dependent read: the second lookup's LOD takes derivatives of the first's result.
    CHECK(matter("void main() { gl_FragColor = texture2D(t, texture2D(t, uv).xy); }"));
    CHECK(matter("void main() { vec4 c = texture2D(t, uv); if (c.a < 0.5) discard; gl_FragColor = c; }"));
    CHECK(matter("void main() { vec4 c = vec4(0.0); for (int i = 0; i < 8; ++i) { c += texture2D(t, uv + c.xy); }"
                 " gl_FragColor = c; }"));
    // Through an array indexed by a lookup, and through a function.
    CHECK(matter("void main() { float a[2]; a[0] = 0.0; a[1] = 0.0; a[int(texture2D(t, uv).r)] = 1.0;"
                 " gl_FragColor = vec4(dFdy(a[0])); }"));
    CHECK(matter("float f(vec2 p) { return texture2D(t, p).r * 2.0; }\n"
                 "void main() { gl_FragColor = vec4(dFdx(f(uv))); }"));
}

}  // namespace glslrun::test
