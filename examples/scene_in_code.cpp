// A scene built in code, without a scene file: the lecture's spot-lit teapot
// (scenes/spot.toml) filled in field by field, as docs/library.md shows.
//
//   scene_in_code shaders/spot_pix_fixed.vert shaders/spot_pix_fixed.frag spot.png [scenes/spot.toml]
//
// With the TOML file, it renders that too and exits 1 unless the two images
// are identical; it always exits 1 when its own picture is blank.
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "glslrun/scene.h"

namespace gs = glslrun::scene;

gs::Scene spot_scene() {
    gs::Scene scene;
    scene.clear_color = {0, 0, 0, 1};
    // The camera: a view matrix, and a projection that resize_scene computes
    // from `camera` (or set scene.projection yourself).
    scene.view = glm::mat4(glm::lookAt(glm::dvec3(0, 0, 5), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0)));
    scene.camera.kind = gs::Camera::Kind::Perspective;
    scene.camera.fovy = 45;
    scene.camera.near = 1;
    scene.camera.far = 100;
    scene.gl.depth_test = true;

    glslrun::MaterialState material;
    material.ambient = {0.25f, 0.20f, 0.07f, 1};
    material.diffuse = {0.75f, 0.61f, 0.23f, 1};
    material.specular = {0.80f, 0.80f, 0.80f, 1};
    material.emission = {0.00f, 0.00f, 0.05f, 1};
    material.shininess = 64;
    scene.gl.front_material = scene.gl.back_material = material;

    // Light 0 keeps GL's white diffuse and specular; position and direction
    // are given in world space (transformed by the view, as glLightfv after
    // gluLookAt).
    glslrun::LightState& light = scene.lights[0].as_given;
    light.ambient = {0.2f, 0.2f, 0.2f, 1};
    light.position = {0.4f, 1.2f, 2.4f, 1};
    light.spot_direction = {-0.1474420f, -0.4423259f, -0.8846517f};
    light.spot_cutoff = 20;
    light.spot_exponent = 12;
    light.constant_attenuation = 1;
    light.linear_attenuation = 0.05f;
    light.quadratic_attenuation = 0.02f;

    gs::Object teapot;
    teapot.name = "teapot";
    teapot.mesh = gs::make_teapot(1.0, 10);  // model stays the identity
    scene.objects.push_back(std::move(teapot));
    return scene;
}

int fail(const glslrun::Error& e) {
    std::fputs(e.str().c_str(), stderr);
    return 1;
}

int main(int argc, char** argv) {
    if (argc != 4 && argc != 5) {
        std::fprintf(stderr, "usage: %s a.vert a.frag out.png [same_scene.toml]\n", argv[0]);
        return 2;
    }
    auto program = gs::compile_files({argv[1]}, {argv[2]});
    if (!program) return fail(program.error());
    gs::Scene scene = spot_scene();
    if (auto sized = gs::resize_scene(scene, 512, 512); !sized) return fail(sized.error());
    auto image = gs::render_image(*program, scene);
    if (!image) return fail(image.error());
    if (auto written = gs::write_png(*image, argv[3]); !written) return fail(written.error());

    // A blank picture is the mistake this example guards against: count the
    // pixels that are not the clear colour.
    size_t lit = 0;
    for (size_t i = 0; i < image->rgba.size(); i += 4)
        lit += image->rgba[i] != 0 || image->rgba[i + 1] != 0 || image->rgba[i + 2] != 0;
    std::printf("wrote %s (%dx%d, %zu lit pixels)\n", argv[3], image->width, image->height, lit);
    if (lit == 0) {
        std::fputs("the picture is blank\n", stderr);
        return 1;
    }
    if (argc == 5) {
        auto from_file = gs::load_scene(argv[4]);
        if (!from_file) return fail(from_file.error());
        auto expected = gs::render_image(*program, *from_file);
        if (!expected) return fail(expected.error());
        gs::CompareOptions exact;
        exact.tolerance = 0;
        exact.min_fraction_within = 1.0;
        auto stats = gs::compare_images(*expected, *image, exact);
        if (!stats) return fail(stats.error());
        std::printf("against %s: %s\n", argv[4], stats->summary().c_str());
        if (expected->rgba != image->rgba) return 1;
    }
    return 0;
}
