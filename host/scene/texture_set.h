// texture_set.h — a scene's textures on the host, in the form the kernels
// read (include/wavefront/scene_types.h, kernels/materials/texture.h): every
// image's texels in one array of RGBA8 words, one image after another (the
// device's copy interleaves some, device/texel_interleave.h), and one
// TextureInfo per (image, sampler, colour space) the materials use. Images
// are decoded here with OpenImageIO, from memory.
//
// Why RGBA8, 4 bytes a texel: DamagedHelmet's five 2048² images take 80 MiB
// so, where float4 would take 320 MiB; the kernels decode a texel with a few
// shifts (and a table lookup for sRGB). 16-bit images lose their low bits.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "wavefront/scene_types.h"

namespace wf {

// An image decoded to RGBA8: grey becomes (L, L, L), a missing alpha 255.
struct DecodedImage {
    uint32_t width = 0, height = 0;
    uint32_t channels = 0;       // in the file: 1 grey, 2 grey+alpha, 3 RGB, 4 (or more) RGBA
    std::vector<uint32_t> texels; // R in the low byte; rows from the top down
};

// R in the low byte, A in the high byte, as texture_texel() reads them.
inline uint32_t pack_rgba8(uint32_t r, uint32_t g, uint32_t b, uint32_t a) {
    return r | g << 8 | b << 16 | a << 24;
}

// Decodes an encoded image (PNG, JPEG, and whatever else OpenImageIO reads
// from memory). `name` (a file name, or empty) helps pick the format; the
// bytes' signature decides for PNG and JPEG. Throws InputError("<where>: ...")
// with OpenImageIO's reason on one line. Alpha stays unassociated (straight),
// as glTF stores it.
DecodedImage decode_image(const unsigned char* bytes, size_t size, const std::string& name,
                          const std::string& where);

struct TextureSet {
    std::vector<TextureInfo> infos;
    std::vector<uint32_t> texels;
    std::vector<std::string> names; // per info, for messages: "image 2 'albedo.png'"

    // Appends an image's texels; returns their offset. Throws InputError
    // ("<where>: ...") when the set would pass 2^32 texels.
    uint32_t add_texels(const DecodedImage& image, const std::string& where);
    // Appends a TextureInfo, its texels together (stride 1: the device's copy
    // may interleave them, device/texel_interleave.h); returns its index.
    int32_t add_info(const TextureInfo& info, const std::string& name);

    size_t bytes() const { return infos.size() * sizeof(TextureInfo) + texels.size() * sizeof(uint32_t); }
};

// A TextureRef naming no texture, with the identity transform and TEXCOORD_0.
TextureRef no_texture();
// A material's WF_TEXTURE_SLOTS, each naming no texture.
std::array<TextureRef, WF_TEXTURE_SLOTS> no_textures();

// KHR_texture_transform's matrix translation * rotation * scale (the
// extension's order: scale first), `rotation` in radians, counter-clockwise
// in uv space as the extension defines it.
std::array<float, 6> texture_transform(float offset_u, float offset_v, float rotation, float scale_u,
                                       float scale_v);

} // namespace wf
