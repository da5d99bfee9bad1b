// A scene file rendered through the public scene API, as
// `glslrun a.vert a.frag scene.toml -o out.png` renders it:
//
//   render_scene shaders/spot_pix_fixed.vert shaders/spot_pix_fixed.frag scenes/spot.toml spot.png
#include <cstdio>

#include "glslrun/scene.h"

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: %s a.vert a.frag scene.toml out.png\n", argv[0]);
        return 2;
    }
    std::printf("glslrun %s\n", GLSLRUN_VERSION_STRING);
    auto image = glslrun::scene::render_files(argv[1], argv[2], argv[3]);
    if (!image) {
        std::fputs(image.error().str().c_str(), stderr);
        return 1;
    }
    if (auto written = glslrun::scene::write_png(*image, argv[4]); !written) {
        std::fputs(written.error().str().c_str(), stderr);
        return 1;
    }
    std::printf("wrote %s (%dx%d)\n", argv[4], image->width, image->height);
    return 0;
}
