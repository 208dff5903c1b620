// test_determinism.cpp — the image depends on the scene, the settings and the
// seed, never on how the work was scheduled: pool sizes (dividing the pixel
// count or not) and local sizes give the same bytes.
#include <cstring>

#include <gtest/gtest.h>

#include "gltf_loader.h"
#include "render_command.h"
#include "renderer.h"
#include "test_support.h"

namespace wf {
namespace {

Image render_cornell(uint32_t pool_size, uint32_t local_size, uint32_t seed) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    RenderSettings settings;
    settings.spp = 4;
    settings.seed = seed;
    settings.pool_size = pool_size;
    settings.local_size = local_size;
    return render_scene(test::cpu_device(), scene, *scene.camera, ImageSize{40, 30}, settings).film.mean;
}

bool same_bytes(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

TEST(Determinism, PoolAndLocalSizeDoNotChangeOneBit) {
    const Image reference = render_cornell(1200, 64, 3); // one slot per pixel
    EXPECT_TRUE(same_bytes(reference, render_cornell(256, 64, 3)));
    EXPECT_TRUE(same_bytes(reference, render_cornell(777, 64, 3))); // does not divide 1200
    EXPECT_TRUE(same_bytes(reference, render_cornell(1200, 32, 3)));
    EXPECT_FALSE(same_bytes(reference, render_cornell(1200, 64, 4))); // the seed does matter
}

// Stopping to look at the film between rounds changes nothing: a pixel's
// samples are still traced and summed in order by its owning slot.
TEST(Determinism, RoundsDoNotChangeOneBit) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    RenderSettings settings;
    settings.seed = 3;
    settings.pool_size = 777;
    Renderer progressive(test::cpu_device(), scene, *scene.camera, ImageSize{40, 30}, settings);
    for (uint32_t spp : {1u, 2u, 3u, 4u}) progressive.render_to(spp);
    EXPECT_TRUE(same_bytes(render_cornell(1200, 64, 3), progressive.read().mean));
}

} // namespace
} // namespace wf
