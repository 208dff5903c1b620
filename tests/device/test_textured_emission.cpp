// test_textured_emission.cpp — the mean of an emissive texture over a
// triangle (host/device/textured_emission.h), which the light table weighs
// textured emitters by: zero exactly where every texel the kernels' lookups
// can read on the triangle is black, whatever the sampler's wrap modes, and
// the texture's mean where the footprint is all of it. The renders that
// check the light table's choice are in tests/render/test_lights.cpp.
#include <cstdint>

#include <gtest/gtest.h>

#include "device/textured_emission.h"
#include "materials/texture.h"
#include "support/test_support.h"

namespace wf {
namespace {

// An emissive quad (two triangles) whose texture coordinates span [u0, u1]
// x [v0, v1], under a side x side texture black but for its column 0, white.
Scene one_quad(float u0, float u1, uint32_t wrap, uint32_t side = 16, float v0 = 0.45f, float v1 = 0.55f) {
    Scene scene;
    const uint32_t m = test::add_material(scene, glm::vec3(0.0f), glm::vec3(1.0f), false);
    test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, m);
    scene.uv0 = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v0}, {u1, v1}, {u0, v1}};
    scene.uv1 = scene.uv0;
    DecodedImage image;
    image.width = image.height = side;
    image.channels = 3;
    for (uint32_t y = 0; y < side; ++y)
        for (uint32_t x = 0; x < side; ++x)
            image.texels.push_back(x == 0 ? pack_rgba8(255, 255, 255, 255) : pack_rgba8(0, 0, 0, 255));
    TextureInfo info{};
    info.offset = scene.textures.add_texels(image, "test");
    info.width = info.height = side;
    info.wrap_s = info.wrap_t = wrap;
    info.channels = 3;
    scene.materials[m].textures[WF_TEXTURE_EMISSIVE].texture = scene.textures.add_info(info, "column 0 white");
    return scene;
}

// A footprint at u in [0.9, 0.99] lies over black texels, but the bilinear
// filter at u = 0.99 reads the texel after column 15: under REPEAT that is
// column 0, and the triangle emits; clamped or mirrored it is column 15, and
// the triangle is black. The kernels' own lookup says the same.
TEST(TexturedEmission, FootprintWrapsAsTheSamplerWraps) {
    for (const uint32_t wrap : {WF_WRAP_REPEAT, WF_WRAP_CLAMP_TO_EDGE, WF_WRAP_MIRRORED_REPEAT}) {
        const Scene scene = one_quad(0.9f, 0.99f, wrap);
        const TexturedEmission textured(scene);
        const TextureRef& ref = scene.materials[0].textures[WF_TEXTURE_EMISSIVE];
        const float lookup =
            wf_device::texture_sample(scene.textures.infos.data(), scene.textures.texels.data(), &ref, {0.99f, 0.5f}).x;
        for (uint32_t t = 0; t < 2; ++t) {
            const double mean = textured.mean(t).x;
            if (wrap == WF_WRAP_REPEAT) {
                EXPECT_GT(lookup, 0.0f);
                EXPECT_GT(mean, 0.0) << "triangle " << t << ", REPEAT";
            } else {
                EXPECT_EQ(lookup, 0.0f) << "wrap " << wrap;
                EXPECT_EQ(mean, 0.0) << "triangle " << t << ", wrap " << wrap;
            }
        }
    }
    // Away from the seam no wrap reaches column 0.
    const Scene middle = one_quad(0.4f, 0.6f, WF_WRAP_REPEAT);
    EXPECT_EQ(TexturedEmission(middle).mean(0).x, 0.0);
}

// A footprint as wide as the texture, or wider, takes the whole texture's
// mean, one white column of the texture's side: texel by texel where the
// texture is small, through the 8 x 8 block sums where it is large.
TEST(TexturedEmission, WideFootprintTakesTheWholeTexturesMean) {
    for (const uint32_t side : {16u, 128u})
        for (const float u1 : {1.0f, 7.5f}) {
            const Scene scene = one_quad(0.0f, u1, WF_WRAP_REPEAT, side, 0.0f, u1);
            const glm::dvec3 mean = TexturedEmission(scene).mean(0);
            EXPECT_NEAR(mean.x, 1.0 / side, 1e-12) << side << " texels a side, u up to " << u1;
            EXPECT_EQ(mean.x, mean.y);
        }
    // A material without an emissive texture: its factor alone.
    Scene plain = one_quad(0.0f, 1.0f, WF_WRAP_REPEAT);
    plain.materials[0].textures[WF_TEXTURE_EMISSIVE].texture = -1;
    EXPECT_EQ(TexturedEmission(plain).mean(0), glm::dvec3(1.0));
}

} // namespace
} // namespace wf
