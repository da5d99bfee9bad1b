// The scene parser's errors: every mistake cites scene.toml and its line and
// says what is wrong, so a typo never passes silently.
#include "glslrun/scene/meshes.h"
#include "parse_helpers.h"

using namespace scene_test;

TEST_CASE("errors print as file:line: error: message", "[scene][errors]") {
    auto r = glslrun::scene::parse_scene("[lights.0]\n\ndifuse = [1, 1, 1]\n", "scene.toml");
    REQUIRE_FALSE(r);
    CHECK(r.error().str() == "scene.toml:3: error: unknown key 'difuse' in [lights.0]; did you mean 'diffuse'?\n");
}

TEST_CASE("TOML syntax errors cite their line", "[scene][errors]") {
    check_cases({
        {"[output]\nsize = [512, 512\n", 2, "TOML syntax error at column 18 (in an array): encountered end-of-file"},
        {"[output]\nclear_color = [0.1 0.2]\n", 2,
         "TOML syntax error at column 20 (in an array): expected comma or closing ']', saw '0'"},
        {"[output\nsize = 1\n", 1, "expected ']'"},
        {"[state]\ndepth_test = true\ndepth_test = false\n", 3, "cannot redefine existing boolean 'depth_test'"},
        {"a = 1 2\n", 1, "expected a comment or whitespace"},
    });
}

TEST_CASE("unknown keys suggest the closest valid key", "[scene][errors]") {
    check_cases({
        {"[outptu]\n", 1, "unknown key 'outptu' at the top level; did you mean 'output'?"},
        {"[output]\nsizes = [1, 1]\n", 2, "unknown key 'sizes' in [output]; did you mean 'size'?"},
        {"[camera]\nlookat = { eye = [0, 0, 5] }\n", 2, "did you mean 'look_at'?"},
        {"[camera]\nlook_at = { eye = [0, 0, 5], centre = [0, 0, 0] }\n", 2,
         "unknown key 'centre' in [camera.look_at]; did you mean 'center'?"},
        {"[camera]\nperspective = { fov = 45, near = 1, far = 10 }\n", 2, "did you mean 'fovy'?"},
        {"[lights.0]\nspot_cuttoff = 20\n", 2, "did you mean 'spot_cutoff'?"},
        {"[light_model]\ntwo_sided = true\n", 2, "did you mean 'two_side'?"},
        {"[material]\nshinyness = 3\n", 2, "did you mean 'shininess'?"},
        {"[front_material]\nemmision = [0, 0, 0]\n", 2, "did you mean 'emission'?"},
        {"[current]\ncolour = [1, 1, 1]\n", 2, "did you mean 'color'?"},
        {"[state]\ndepth_tset = true\n", 2, "did you mean 'depth_test'?"},
        {"[fog]\ndensty = 1\n", 2, "did you mean 'density'?"},
        {"[texture_matrix.0]\ntransfrom = []\n", 2, "did you mean 'transform'?"},
        {"[[objects]]\nmesh = \"quad\"\ncolr = [1, 1, 1]\n", 3, "did you mean 'color'?"},
        {"[[objects]]\nmesh = \"quad\"\n[objects.material]\ndifuse = [1, 1, 1]\n", 4,
         "in [objects[0].material]; did you mean 'diffuse'?"},
        {"[[objects]]\nmesh = \"quad\"\ntransform = [ { rotat = [1, 0, 0, 1] } ]\n", 3, "did you mean 'rotate'?"},
        {"[state]\nxyzzy = 1\n", 2, "unknown key 'xyzzy' in [state]; valid keys: depth_test, depth_func"},
        // Two unknown keys: the first in the file is reported, not the first alphabetically.
        {"[fog]\nzz = 1\naa = 2\n", 2, "unknown key 'zz'"},
    });
}

TEST_CASE("wrong types and lengths", "[scene][errors]") {
    check_cases({
        {"[lights.0]\ndiffuse = \"red\"\n", 2,
         "'lights.0.diffuse' must be an array of 3 or 4 numbers (got the string \"red\")"},
        {"[lights.0]\ndiffuse = [1, 1]\n", 2, "'lights.0.diffuse' must be an array of 3 or 4 numbers"},
        {"[lights.0]\ndiffuse = [1, 1, \"x\"]\n", 2, "'lights.0.diffuse[2]' must be a number"},
        {"[lights.0]\nposition = [1, 1, 1]\n", 2, "'lights.0.position' must be an array of 4 numbers"},
        {"[lights.0]\nspot_direction = [1, 1, 1, 0]\n", 2, "'lights.0.spot_direction' must be an array of 3 numbers"},
        {"[lights.0]\nenabled = 1\n", 2, "'lights.0.enabled' must be true or false (got the integer 1)"},
        {"[lights.0]\nspace = \"wrld\"\n", 2, "'lights.0.space' = \"wrld\" is not allowed; did you mean 'world'?"},
        {"lights = 3\n", 1, "'lights' must be a table"},
        {"[output]\nsize = 512\n", 2, "'output.size' must be [width, height]"},
        {"[output]\nsize = [512.5, 512]\n", 2, "'output.size[0]' must be an integer"},
        {"[output]\nclear_depth = true\n", 2, "'output.clear_depth' must be a number"},
        {"[camera]\nview_matrix = [1, 2, 3]\n", 2, "'camera.view_matrix' must be a matrix: 16 numbers"},
        {"[camera]\nprojection_matrix = [[1, 0, 0, 0], [0, 1, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\n", 2,
         "'camera.projection_matrix[1]' must be an array of 4 numbers"},
        {"[state]\ndepth_func = \"lequl\"\n", 2, "did you mean 'lequal'?"},
        {"[state]\ncull_face = true\n", 2, "'state.cull_face' must be one of \"off\", \"back\""},
        {"[state]\nclip_planes = [[0, 0, 1]]\n", 2, "'state.clip_planes[0]' must be an array of 4 numbers"},
        {"[texture_matrix.0]\ntransform = { scale = [1, 1, 1] }\n", 2, "'texture_matrix.0.transform' must be an array"},
        {"objects = 3\n", 1, "'objects' must be an array of tables ([[objects]])"},
        {"[[objects]]\nmesh = \"quad\"\ntransform = [ { scale = [1, 1] } ]\n", 3,
         "'objects[0].transform[0].scale' must be an array of 3 numbers"},
        {"[[objects]]\nmesh = \"quad\"\ntransform = [ { scale = [1, 1, 1], translate = [0, 0, 0] } ]\n", 3,
         "must have exactly one of translate, rotate, scale, matrix"},
        {"[[objects]]\nmesh = \"quad\"\nname = 3\n", 3, "'objects[0].name' must be a string"},
        {"[[objects]]\nmesh = \"quad\"\nvertex_colors = \"normals\"\n", 3, "did you mean 'normal'?"},
    });
}

TEST_CASE("values outside GL's ranges", "[scene][errors]") {
    check_cases({
        {"[lights.0]\nspot_cutoff = 120\n", 2,
         "'lights.0.spot_cutoff' must be in [0, 90] or exactly 180 (GL's allowed values for GL_SPOT_CUTOFF"},
        {"[lights.0]\nspot_cutoff = -1\n", 2, "in [0, 90] or exactly 180"},
        {"[lights.0]\nspot_exponent = 129\n", 2, "'lights.0.spot_exponent' must be in [0, 128] (GL_SPOT_EXPONENT); got 129"},
        {"[lights.0]\nlinear_attenuation = -0.5\n", 2, "'lights.0.linear_attenuation' must be >= 0"},
        {"[lights.0]\nconstant_attenuation = -1\n", 2, "must be >= 0"},
        {"[lights.0]\nquadratic_attenuation = -1\n", 2, "must be >= 0"},
        {"[material]\nshininess = 200\n", 2, "'material.shininess' must be in [0, 128] (GL_SHININESS); got 200"},
        {"[back_material]\nshininess = -1\n", 2, "'back_material.shininess' must be in [0, 128]"},
        {"[lights.8]\ndiffuse = [1, 1, 1]\n", 1, "'lights.8': there are at most 8 lights, 0..7 (GL_LIGHT0..GL_LIGHT7)"},
        {"[lights.first]\n", 1, "'lights.first': there are at most 8 lights"},
        {"[lights.0]\n[lights.00]\n", 2, "'lights.00': there are at most 8 lights"},
        {"[texture_matrix.8]\n", 1, "texture units are 0..7"},
        {"[output]\nclear_depth = 2\n", 2, "'output.clear_depth' must be in [0, 1]"},
        {"[state]\npoint_size = 0\n", 2, "'state.point_size' must be > 0"},
        {"[state]\ndepth_range = [0, 1.5]\n", 2, "'state.depth_range[1]' must be in [0, 1]"},
        {"[state]\nclip_planes = [[0,0,1,0],[0,0,1,0],[0,0,1,0],[0,0,1,0],[0,0,1,0],[0,0,1,0],[0,0,1,0]]\n", 2,
         "has 7 planes; GL has 6"},
        {"[camera]\nview_matrix = [0,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]\n[state]\nclip_planes = [[0, 0, 1, 0]]\n", 4,
         "the view matrix is singular"},
        {"[state]\nclip_planes_space = \"world \"\n", 2, "did you mean 'world'?"},
        {"[fog]\ndensity = -1\n", 2, "'fog.density' must be >= 0"},
    });
}

TEST_CASE("output sizes are checked before anything is allocated", "[scene][errors]") {
    check_cases({
        {"[output]\nsize = [100000, 100000]\n", 2,
         "size 100000x100000 is not allowed: width and height must each be 1..16384"},
        {"[output]\nsize = [0, 512]\n", 2, "size 0x512 is not allowed"},
        // Issue #17: each side is allowed, but 16384^2 pixels would need 5 GiB.
        {"[output]\nsize = [16384, 16384]\n", 2, "size 16384x16384 is not allowed: width and height must each be 1..16384, and 64M pixels at most"},
        {"[output]\nsize = [-512, 512]\n", 2, "size -512x512 is not allowed"},
        {"[output]\nsize = [512, 9223372036854775807]\n", 2, "is not allowed"},
        {"[output]\nsize = [512]\n", 2, "must be [width, height]"},
    });
    CHECK(parse_ok("[output]\nsize = [16384, 1]\n").width == 16384);
}

// Issue #17 (found by fuzz_scene's long run): every object keeps its own GL
// state, so a 64 MiB scene of 2.8M quads needed 14 GB; and each mesh is
// bounded, but not a scene of many of the largest.
TEST_CASE("a scene's objects and their vertices are bounded", "[scene][errors]") {
    std::string quads;
    for (size_t i = 0; i <= glslrun::scene::kMaxSceneObjects; ++i) quads += "[[objects]]\nmesh = \"quad\"\n";
    check_error(quads, 1, "the scene has 65537 objects; a scene may have at most 65536");
    std::string planes;
    for (int i = 0; i < 8; ++i) planes += "[[objects]]\nmesh = \"plane\"\nsubdivisions = 1024\n";
    // Each plane has 1025^2 vertices: the eighth passes 8M.
    check_error(planes, 22, "the objects up to objects[7] have 8405000 vertices in all; a scene may have at most 8388608");
    planes.resize(planes.size() / 8 * 7);
    CHECK(parse_ok(planes).objects.size() == 7);
}

TEST_CASE("NaN, infinity and numbers beyond a float are refused", "[scene][errors]") {
    check_cases({
        {"[output]\nclear_color = [nan, 0, 0]\n", 2, "'output.clear_color[0]' must be a finite number"},
        {"[output]\nclear_depth = inf\n", 2, "'output.clear_depth' must be a finite number"},
        {"[lights.0]\nposition = [0, 0, -inf, 1]\n", 2, "must be a finite number"},
        {"[uniforms]\nx = nan\n", 2, "'x' must be a finite number"},
        {"[uniforms]\nm = [[1, 0], [0, +inf]]\n", 2, "'m[1][1]' must be a finite number"},
        {"[fog]\nstart = 1e39\n", 2, "'fog.start' = 1e+39 does not fit in a float"},
        {"[[objects]]\nmesh = \"quad\"\ntransform = [ { rotate = [nan, 0, 0, 1] } ]\n", 3, "must be a finite number"},
    });
}

TEST_CASE("camera mistakes", "[scene][errors]") {
    check_cases({
        {"[camera]\nperspective = { fovy = 45, near = 0, far = 100 }\n", 2, "'camera.perspective.near' must be > 0"},
        {"[camera]\nperspective = { fovy = 45, near = 2, far = 2 }\n", 2, "near and far must differ"},
        {"[camera]\nperspective = { near = 1, far = 100 }\n", 2, "[camera.perspective] needs 'fovy'"},
        {"[camera]\nperspective = { fovy = 180, near = 1, far = 100 }\n", 2, "'camera.perspective.fovy' must be in (0, 180)"},
        {"[camera]\nperspective = { fovy = 45, aspect = 0, near = 1, far = 100 }\n", 2, "'camera.perspective.aspect' must be > 0"},
        {"[camera]\nfrustum = { left = -1, right = 1, bottom = -1, top = 1, near = -1, far = 10 }\n", 2,
         "'camera.frustum.near' must be > 0"},
        {"[camera]\northo = { left = 1, right = 1, bottom = -1, top = 1, near = -1, far = 1 }\n", 2,
         "left and right must differ"},
        {"[camera]\northo = { left = -1, right = 1, bottom = -1, top = 1, far = 1 }\n", 2, "needs 'near'"},
        {"[camera]\nperspective = { fovy = 45, near = 1, far = 100 }\n\northo = { left = -1 }\n", 4,
         "[camera] has both 'perspective' and 'ortho'; give only one"},
        {"[camera]\nlook_at = { eye = [0, 0, 5] }\nview_matrix = [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]\n", 3,
         "has both 'look_at' and 'view_matrix'"},
        {"[camera]\nlook_at = { eye = [1, 2, 3], center = [1, 2, 3] }\n", 2, "eye and center must differ"},
        {"[camera]\nlook_at = { eye = [0, 5, 0], center = [0, 0, 0], up = [0, 1, 0] }\n", 2,
         "up must not be zero or parallel to the viewing direction"},
    });
}

TEST_CASE("object mistakes", "[scene][errors]") {
    check_cases({
        {"[[objects]]\nmesh = \"teapt\"\n", 2, "'objects[0].mesh' = \"teapt\" is not allowed; did you mean 'teapot'?"},
        {"[[objects]]\nname = \"x\"\n", 1, "[objects[0]] needs 'mesh'"},
        {"[[objects]]\nmesh = \"teapot\"\nsubdivisions = 0\n", 3, "'objects[0].subdivisions' must be in [1, 256]; got 0"},
        {"[[objects]]\nmesh = \"teapot\"\nsubdivisions = 257\n", 3, "must be in [1, 256]; got 257"},
        {"[[objects]]\nmesh = \"plane\"\nsubdivisions = 2.5\n", 3, "must be an integer"},
        {"[[objects]]\nmesh = \"sphere\"\nslices = 2\n", 3, "'objects[0].slices' must be in [3, 1024]"},
        {"[[objects]]\nmesh = \"teapot\"\nsize = -1\n", 3, "'objects[0].size' must be > 0"},
        {"[[objects]]\nmesh = \"sphere\"\nradius = 0\n", 3, "'objects[0].radius' must be > 0"},
        {"[[objects]]\nmesh = \"teapot\"\nradius = 2\n", 3, "'radius' does not apply to mesh 'teapot' (it takes size, subdivisions)"},
        {"[[objects]]\nmesh = \"quad\"\nsize = 2\n", 3, "'size' does not apply to mesh 'quad' (it takes no parameters)"},
        {"[[objects]]\nmesh = \"obj\"\n", 1, "needs 'file'"},
        {"[[objects]]\nmesh = \"quad\"\n[[objects]]\nmesh = \"quad\"\ntransform = [ { rotate = [30, 0, 0, 0] } ]\n", 5,
         "'objects[1].transform[0].rotate': the rotation axis must not be (0, 0, 0)"},
        {"[[objects]]\nmesh = \"quad\"\ncolor = [1, 0]\n", 3, "'objects[0].color' must be an array of 3 or 4 numbers"},
        {"[[objects]]\nmesh = \"quad\"\ntransform = [ { rotate = [0, 1, 0] } ]\n", 3,
         "'objects[0].transform[0].rotate' must be [angle in degrees, x, y, z]"},
        {"[[objects]]\nmesh = \"quad\"\n[objects.front_material]\nshininess = 300\n", 4,
         "'objects[0].front_material.shininess' must be in [0, 128]"},
    });
}

TEST_CASE("attribute mistakes", "[scene][errors]") {
    const std::string quad = "[[objects]]\nmesh = \"quad\"\n[objects.attributes]\n";
    check_cases({
        {(quad + "w = [1, 2, 3]\n").c_str(), 4, "attribute 'w' has 3 values; the mesh has 4 vertices"},
        {(quad + "w = [1, [2, 3], 3, 4]\n").c_str(), 4, "'objects[0].attributes.w[1]' has 2 components; element 0 has 1"},
        {(quad + "w = [[1,2,3,4,5], [1], [1], [1]]\n").c_str(), 4, "'objects[0].attributes.w[0]' must be an array of 1 to 4 numbers"},
        {(quad + "w = [true, 1, 1, 1]\n").c_str(), 4, "must be a number (got true)"},
        {(quad + "gl_Color = [1, 1, 1, 1]\n").c_str(), 4, "'gl_Color' is a built-in attribute"},
        {(quad + "\"my attr\" = [1, 1, 1, 1]\n").c_str(), 4, "'my attr' is not a GLSL attribute name"},
        {(quad + "w = 1\n").c_str(), 4, "'objects[0].attributes.w' must be an array"},
    });
}

TEST_CASE("uniform mistakes", "[scene][errors]") {
    check_cases({
        {"[uniforms]\nname = \"x\"\n", 2, "uniform 'name' must hold numbers or booleans (got the string \"x\")"},
        {"[uniforms]\nm = [[1, 0, 0], [0, 1]]\n", 2, "uniform 'm': every element must have the same shape"},
        {"[uniforms]\nv = [1, [2, 3]]\n", 2, "every element must have the same shape"},
        {"[uniforms]\nv = []\n", 2, "uniform 'v' must hold numbers or booleans"},
        {"[uniforms]\ns = {}\n", 2, "uniform struct 's' is empty"},
        {"[uniforms]\ns = [{ a = 1 }, 2]\n", 2, "uniform 's[1]' must be a table like the elements before it"},
        {"[uniforms]\nb = [true, 0.5]\n", 2, "mixes booleans and fractional numbers"},
        {"[uniforms]\ngl_Color = [1, 1, 1, 1]\n", 2, "'gl_Color' is a built-in uniform"},
        {"uniforms = [1]\n", 1, "'uniforms' must be a table"},
        {"[[objects]]\nmesh = \"quad\"\n[objects.uniforms]\nt = \"x\"\n", 4, "uniform 't' must hold numbers"},
    });
}
