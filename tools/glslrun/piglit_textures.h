// shader_runner's texture commands on a GLState: the textures piglit's
// helpers build (piglit_rgbw_texture, piglit_checkerboard_texture,
// piglit_depth_texture, piglit_rgbw_texture_1d/_3d) with the sampler state
// those helpers set, and texparameter.
#pragma once
#include <cstdint>

#include "glslrun/glslrun.h"
#include "piglit_parse.h"

namespace glslrun::piglit {

// GL allows 16384x16384 RGBA textures; at 16 bytes a texel that is 4 GiB
// here, so the runner refuses textures above this many texels (64 MiB).
inline constexpr int64_t kMaxRunnerTexels = int64_t(1) << 22;

// Level 0 of the texture a command uploads, texels as GL receives them
// (before the internal format rounds them). Sizes must have been checked.
TextureImage rgbw_image(int width, int height);
TextureImage rgbw_1d_image();
TextureImage rgbw_3d_image();
TextureImage checkerboard_image(int width, int height, const glm::vec4& black, const glm::vec4& white);
TextureImage depth_ramp_image(int width, int height);

// The texture object a command creates: image, internal format and sampler
// state. Errors: sizes that are empty, past GL's maxima or past
// kMaxRunnerTexels, and checkerboards smaller than 2x2 (piglit divides by w/2).
Result<Texture> make_texture(const TextureCommand& cmd);

// Tracks glActiveTexture, which texparameter follows.
struct TextureState {
    int active_unit = 0;
};

// glActiveTexture(unit) plus the helper's glBindTexture on that unit.
Status run_texture_command(GLState& gl, TextureState& state, const TextureCommand& cmd);
// glTexParameter on the texture bound to the target on the active unit; with
// none bound, GL changes texture object 0, which nothing here samples.
Status run_texparameter(GLState& gl, const TextureState& state, const TexParameter& p);

}  // namespace glslrun::piglit
