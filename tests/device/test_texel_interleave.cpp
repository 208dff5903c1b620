// test_texel_interleave.cpp — the device's texel buffer
// (host/device/texel_interleave.h): every TextureInfo reads what it reads in
// the scene's own set at every texel, and the images one material reads at
// the same texel sit side by side, while those it reads elsewhere do not.
#include <cstdint>
#include <cstdlib>

#include <gtest/gtest.h>

#include "device/texel_interleave.h"
#include "materials/texture.h"
#include "support/test_support.h"

namespace wf {
namespace {

DecodedImage random_image(uint32_t width, uint32_t height, uint32_t seed) {
    DecodedImage image;
    image.width = width;
    image.height = height;
    image.channels = 4;
    for (uint32_t i = 0; i < width * height; ++i) image.texels.push_back(seed * 2654435761u + i * 40503u);
    return image;
}

int32_t add_texture(Scene& scene, uint32_t offset, uint32_t side, uint32_t flags,
                    uint32_t wrap = WF_WRAP_REPEAT) {
    TextureInfo info{};
    info.offset = offset;
    info.width = info.height = side;
    info.wrap_s = info.wrap_t = wrap;
    info.flags = flags;
    info.channels = 4;
    return scene.textures.add_info(info, "test");
}

// Material 0 reads four 8x8 images at one texel (one of them twice, as
// sRGB base colour and as linear emission), a 4x4 image, and an 8x8 one
// through a scaled transform; material 1 reads the scaled image and one of
// material 0's, already placed; material 2 reads image 6 through two
// samplers, each beside a partner (image 7 under the first, 8 under the
// second), so at two texels: it goes with the first.
Scene textured_scene() {
    Scene scene;
    const uint32_t m0 = test::add_material(scene, glm::vec3(1.0f), glm::vec3(0.0f), false);
    const uint32_t m1 = test::add_material(scene, glm::vec3(1.0f), glm::vec3(0.0f), false);
    const uint32_t m2 = test::add_material(scene, glm::vec3(1.0f), glm::vec3(0.0f), false);
    test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, m0);
    std::vector<uint32_t> image;
    for (uint32_t i = 0; i < 9; ++i)
        image.push_back(scene.textures.add_texels(random_image(i == 4 ? 4 : 8, i == 4 ? 4 : 8, i + 1), "test"));
    auto& t0 = scene.materials[m0].textures;
    t0[WF_TEXTURE_BASE_COLOR].texture = add_texture(scene, image[0], 8, WF_TEXTURE_SRGB);
    t0[WF_TEXTURE_METALLIC_ROUGHNESS].texture = add_texture(scene, image[1], 8, 0);
    t0[WF_TEXTURE_NORMAL].texture = add_texture(scene, image[2], 8, 0);
    t0[WF_TEXTURE_EMISSIVE].texture = add_texture(scene, image[0], 8, 0);
    t0[WF_TEXTURE_CLEARCOAT].texture = add_texture(scene, image[3], 8, 0);
    t0[WF_TEXTURE_SPECULAR].texture = add_texture(scene, image[4], 4, 0);
    t0[WF_TEXTURE_TRANSMISSION].texture = add_texture(scene, image[5], 8, 0);
    t0[WF_TEXTURE_TRANSMISSION].transform[0] = 3.0f;
    auto& t1 = scene.materials[m1].textures;
    t1[WF_TEXTURE_BASE_COLOR] = t0[WF_TEXTURE_TRANSMISSION];
    t1[WF_TEXTURE_NORMAL] = t0[WF_TEXTURE_NORMAL];
    auto& t2 = scene.materials[m2].textures;
    t2[WF_TEXTURE_BASE_COLOR].texture = add_texture(scene, image[6], 8, 0);
    t2[WF_TEXTURE_METALLIC_ROUGHNESS].texture = add_texture(scene, image[7], 8, 0);
    t2[WF_TEXTURE_NORMAL].texture = add_texture(scene, image[6], 8, 0, WF_WRAP_CLAMP_TO_EDGE);
    t2[WF_TEXTURE_EMISSIVE].texture = add_texture(scene, image[8], 8, 0, WF_WRAP_CLAMP_TO_EDGE);
    return scene;
}

TEST(TexelInterleave, EveryTextureReadsItsOwnTexels) {
    const Scene scene = textured_scene();
    const InterleavedTexels device = interleave_texels(scene);
    ASSERT_EQ(device.infos.size(), scene.textures.infos.size());
    EXPECT_EQ(device.texels.size(), scene.textures.texels.size());
    for (size_t i = 0; i < device.infos.size(); ++i) {
        const TextureInfo& before = scene.textures.infos[i];
        const TextureInfo& after = device.infos[i];
        for (uint32_t y = 0; y < before.height; ++y)
            for (uint32_t x = 0; x < before.width; ++x) {
                const auto a = wf_device::texture_texel(&before, scene.textures.texels.data(), x, y);
                const auto b = wf_device::texture_texel(&after, device.texels.data(), x, y);
                ASSERT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w)
                    << "texture " << i << ", texel (" << x << ", " << y << ")";
            }
    }
}

TEST(TexelInterleave, OneMaterialsTexelsSitSideBySide) {
    const Scene scene = textured_scene();
    const InterleavedTexels device = interleave_texels(scene);
    const auto& t0 = scene.materials[0].textures;
    const auto info = [&](uint32_t slot) { return device.infos[size_t(t0[slot].texture)]; };
    // The four 8x8 images material 0 reads at one texel: base colour
    // (emission shares its image), metallic-roughness, normal, clear coat.
    for (const uint32_t slot : {WF_TEXTURE_BASE_COLOR, WF_TEXTURE_METALLIC_ROUGHNESS, WF_TEXTURE_NORMAL,
                                WF_TEXTURE_EMISSIVE, WF_TEXTURE_CLEARCOAT}) {
        EXPECT_EQ(info(slot).stride, 4u) << "slot " << slot;
        EXPECT_LT(std::abs(int64_t(info(slot).offset) - int64_t(info(WF_TEXTURE_BASE_COLOR).offset)), 4)
            << "slot " << slot;
    }
    EXPECT_EQ(info(WF_TEXTURE_EMISSIVE).offset, info(WF_TEXTURE_BASE_COLOR).offset);
    // Another size, another transform: read elsewhere, kept whole.
    EXPECT_EQ(info(WF_TEXTURE_SPECULAR).stride, 1u);
    EXPECT_EQ(info(WF_TEXTURE_TRANSMISSION).stride, 1u);
    // An image read at two texels: with the first sampler's partner, once.
    const auto& t2 = scene.materials[2].textures;
    const auto info2 = [&](uint32_t slot) { return device.infos[size_t(t2[slot].texture)]; };
    EXPECT_EQ(info2(WF_TEXTURE_BASE_COLOR).stride, 2u);
    EXPECT_EQ(info2(WF_TEXTURE_NORMAL).offset, info2(WF_TEXTURE_BASE_COLOR).offset);
    EXPECT_EQ(info2(WF_TEXTURE_EMISSIVE).stride, 1u);
}

} // namespace
} // namespace wf
