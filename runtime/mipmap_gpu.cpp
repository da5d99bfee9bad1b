// NVIDIA's glGenerateMipmap (driver 580.159 on an H200), measured by
// tools/gpu_probes/mipgen.frag: every texel of five generated levels of a
// random 128x128 RGBA texture and of scenes/textures/wood.png. Each texel of
// a level is the texture unit's bilinear blend at the centre of its block of
// 2x2 texels (2 where a side is already 1) above, in the unit's 16-bit values
// (runtime/sampling_gpu.h: byte b as 257 b, each texel weighted 256 / n of
// 256, the sum rounded to 16 bits), stored by the GPU's UNORM8 rule
// (raster::gpu_unorm8): for the block's byte sum S,
//   byte = gpu_unorm8(((257 S 256/n + 128) >> 8) / 65535).
// Rounding the block's mean to nearest, as glslrun's Texture::generate_mipmaps
// does, gives another byte on 0.4 to 0.6% of those texels (where the mean of
// the bytes ends in exactly 1/2, the GPU rounds down).
#include "runtime/mipmap_gpu.h"

#include "raster/framebuffer.h"
#include "runtime/texture_levels.h"

namespace glslrun::rt {

namespace {

// The level below `src`, whose sides are each 1 or even.
TextureImage reduce_gpu(const TextureImage& src) {
    const int w = half_size(src.width), h = half_size(src.height);
    const int sx = src.width / w, sy = src.height / h;  // 1 or 2
    const int weight = 256 / (sx * sy);
    TextureImage out{w, h, 1, std::vector<glm::vec4>(size_t(w) * size_t(h))};
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            for (int c = 0; c < 4; ++c) {
                int sum = 0;
                for (int y = 0; y < sy; ++y)
                    for (int x = 0; x < sx; ++x) {
                        const float v = src.texels[size_t(i * sx + x) + size_t(src.width) * size_t(j * sy + y)][c];
                        sum += int(v * 255.0f + 0.5f);  // an RGBA8 texel k/255 as its byte
                    }
                const int r16 = (257 * sum * weight + 128) >> 8;
                const int byte = raster::gpu_unorm8<int32_t>(float(r16) / 65535.0f);
                out.texels[size_t(i) + size_t(w) * size_t(j)][c] = float(byte) / 255.0f;
            }
    return out;
}

bool halves_exactly(const TextureImage& image) {
    for (int side : {image.width, image.height})
        for (int n = side; n > 1; n /= 2)
            if (n % 2) return false;
    return image.depth == 1;
}

}  // namespace

bool generate_gpu_mipmaps(Texture& texture) {
    const TextureTarget target = texture.target();
    if (texture.format() != TextureFormat::RGBA8 || target == TextureTarget::Tex3D || target == TextureTarget::Rect)
        return false;
    const int base = texture.sampler.base_level;
    for (int f = 0; f < texture.faces(); ++f) {
        const TextureImage* image = level_image(texture, f, base);
        if (!image || !halves_exactly(*image)) return false;
    }
    const int q = last_mip_level(*level_image(texture, 0, base), texture.sampler);
    for (int f = 0; f < texture.faces(); ++f)
        for (int level = base + 1; level <= q; ++level)
            if (!texture.set_level(f, level, reduce_gpu(*level_image(texture, f, level - 1))))
                return false;  // a level beyond GL's limit: generate_mipmaps() stops there too
    return true;
}

}  // namespace glslrun::rt
