// glslrun's scene library (glslrun::scene): everything around a draw that a
// program needs to render what the command line renders.
//
//   auto image = glslrun::scene::render_files("spot.vert", "spot.frag", "spot.toml");
//   if (!image) { std::fputs(image.error().str().c_str(), stderr); return 1; }
//   glslrun::scene::write_png(*image, "spot.png");
//
// - scene/scene.h: scene files (docs/scene-format.md): load_scene, parse_scene,
//   or a Scene built in code; resize_scene.
// - scene/render.h: render_scene, render_image, compile_files, render_files.
// - scene/meshes.h: the built-in meshes (teapot, quad, cube, ...) and OBJ files.
// - scene/texture_images.h: texture images from files and patterns.
// - scene/image_compare.h: RGBA8 images, PNG reading and writing, comparison.
// - scene/error_report.h: one precision mode measured against Reference.
// - scene/undefined.h: the operations GLSL leaves undefined that a render computes.
#pragma once
#include "glslrun/glslrun.h"
#include "glslrun/scene/error_report.h"
#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/meshes.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"
#include "glslrun/scene/texture_images.h"
#include "glslrun/scene/undefined.h"
