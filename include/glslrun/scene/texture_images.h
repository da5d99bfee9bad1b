// Texel sources for [textures.N] (docs/scene-format.md): PNG and JPEG files
// read with stb_image, and the procedural patterns piglit and the lectures
// use (checkerboard, piglit's rgbw quadrants, a solid colour).
//
// Every image is RGBA as glTexImage receives it: texel (i, j, k) at
// texels[i + w * (j + h * k)], j = 0 the first row GL receives (t = 0).
#pragma once
#include <array>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "glslrun/glslrun.h"

namespace glslrun::scene {

// All images of one texture together (faces, given levels) may hold at most this many
// texels (16M: 256 MiB as glslrun's float texels). Checked before decoding
// or generating anything; GL_MAX_TEXTURE_SIZE alone would allow 4 GiB.
inline constexpr int64_t kMaxTextureTexels = int64_t(1) << 24;
// All textures of a scene together, generated mipmaps included (32M: 512 MiB,
// two textures of 4096x4096); each is counted once built, so a scene holds at
// most this plus one texture. 16 units of 4096x4096 took 4.5 GB and 42 s.
inline constexpr int64_t kMaxSceneTexels = int64_t(1) << 25;
// Image files larger than this are refused before they are read.
inline constexpr int64_t kMaxTextureFileBytes = int64_t(256) << 20;

// A PNG or JPEG file as RGBA texels in [0, 1]: grey becomes (L, L, L, 1) as
// GL_LUMINANCE does, no alpha means 1, 16-bit channels are reduced to 8 bits,
// no gamma is applied. The header is checked (format, each side
// 1..kMaxTextureSize, kMaxTextureTexels in all) before anything is decoded.
// `bottom_up`: the file's last row becomes row 0 (t = 0), so the picture
// appears upright with t pointing up, as a GL program that flips its images
// sees it; false keeps the file's top row as row 0 (cube map faces).
// Errors name the file and say what is wrong.
Result<TextureImage> read_texture_image(const std::string& path, bool bottom_up);

// Image sizes: width, height, depth (unused dimensions 1).
using Size3 = std::array<int, 3>;

// Squares of square_size texels, colors[0] at texel (0, 0, 0) and
// alternating along every axis.
TextureImage checkerboard_image(Size3 size, Size3 square_size, const std::array<glm::vec4, 2>& colors);
// piglit's rgbw texture (piglit_rgbw_image_ubyte): quadrants red (s < 1/2,
// t < 1/2), green (s >= 1/2, t < 1/2), blue (s < 1/2, t >= 1/2) and white.
// With `alpha` their alphas are 0, 64/255, 128/255 and 1 as piglit's. A 1D
// image is red, green, blue, white quarters (piglit_rgbw_texture_1d); a 3D
// one octants red, green, blue, white, yellow, magenta, cyan, black
// (piglit_rgbw_texture_3d), s fastest. `dimensions` (1..3) picks the layout.
TextureImage rgbw_image(Size3 size, int dimensions, bool alpha);
TextureImage solid_image(Size3 size, glm::vec4 color);

}  // namespace glslrun::scene
