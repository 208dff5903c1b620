// test_aovs.cpp — --aov albedo,normal,depth: the first hit's base colour,
// shading normal and distance, as a pixel's mean over its samples. A wall of
// known colour square to the camera gives them exactly (the distance to
// within the pixel's footprint), escaped rays give zeros, asking for them
// changes no byte of the image, and they have the same bytes on any pool,
// schedule and number of devices.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "gltf/gltf_loader.h"
#include "render/renderer.h"
#include "support/test_support.h"

namespace wf {
namespace {

constexpr uint32_t kAll = WF_AOV_ALBEDO | WF_AOV_NORMAL | WF_AOV_DEPTH;

bool same_bytes(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

// A wall at z = -2 filling the left half of the view, nothing on the right:
// the camera at the origin looks down -z with a 60° field of view.
struct WallScene {
    Scene scene;
    SceneCamera camera = test::camera_looking({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, glm::radians(60.0f));
    WallScene() {
        const uint32_t m = test::add_material(scene, {0.2f, 0.5f, 0.8f}, {0, 0, 0}, false);
        test::add_quad(scene, {-10, -10, -2}, {0, -10, -2}, {0, 10, -2}, {-10, 10, -2}, m);
        scene.environment = nullptr;
        test::add_material(scene, {0, 0, 0}, {1, 1, 1}, false); // an emitter out of view, so the scene has light
        test::add_quad(scene, {-1, 5, 1}, {1, 5, 1}, {1, 5, 3}, {-1, 5, 3}, 1);
    }
};

FilmReadout render_wall(uint32_t aovs) {
    const WallScene wall;
    RenderSettings settings;
    settings.spp = 16;
    settings.aovs = aovs;
    return render_scene(test::cpu_device(), wall.scene, wall.camera, ImageSize{32, 32}, settings).film;
}

TEST(Aovs, AWallSquareToTheCameraGivesItsColourNormalAndDistance) {
    const FilmReadout film = render_wall(kAll);
    ASSERT_TRUE(film.albedo && film.normal && film.depth);
    const float tan_half = std::tan(glm::radians(30.0f));
    int walls = 0, misses = 0;
    for (uint32_t y = 0; y < 32; ++y)
        for (uint32_t x = 0; x < 32; ++x) {
            const size_t p = size_t{y} * 32 + x;
            const float* albedo = &film.albedo->rgb[3 * p];
            const float* normal = &film.normal->rgb[3 * p];
            const float depth = film.depth->rgb[3 * p];
            if (x >= 16) { // the right half sees nothing
                EXPECT_EQ(albedo[0] + albedo[1] + albedo[2] + normal[2] + depth, 0.0f) << x << "," << y;
                ++misses;
                continue;
            }
            EXPECT_NEAR(albedo[0], 0.2f, 1e-6f) << x << "," << y;
            EXPECT_NEAR(albedo[1], 0.5f, 1e-6f);
            EXPECT_NEAR(albedo[2], 0.8f, 1e-6f);
            EXPECT_NEAR(normal[0], 0.0f, 1e-6f);
            EXPECT_NEAR(normal[1], 0.0f, 1e-6f);
            EXPECT_NEAR(normal[2], 1.0f, 1e-6f);
            // The distance to the wall along the pixel's rays lies between its
            // corners' and its centre's, 2 / cos(angle off the axis).
            auto distance = [&](float px, float py) {
                const float sx = (2.0f * px / 32.0f - 1.0f) * tan_half, sy = (1.0f - 2.0f * py / 32.0f) * tan_half;
                return 2.0f * std::sqrt(1.0f + sx * sx + sy * sy);
            };
            const float low = std::min({distance(x, y), distance(x + 1, y), distance(x, y + 1), distance(x + 1, y + 1)});
            const float high = std::max({distance(x, y), distance(x + 1, y), distance(x, y + 1), distance(x + 1, y + 1)});
            EXPECT_GE(depth, low - 1e-5f) << x << "," << y;
            EXPECT_LE(depth, high + 1e-5f) << x << "," << y;
            ++walls;
        }
    EXPECT_EQ(walls, 512);
    EXPECT_EQ(misses, 512);
}

TEST(Aovs, AskingForThemChangesNoByteOfTheImage) {
    EXPECT_TRUE(same_bytes(render_wall(0).mean, render_wall(kAll).mean));
    EXPECT_FALSE(render_wall(0).albedo.has_value());
    const FilmReadout albedo_only = render_wall(WF_AOV_ALBEDO);
    EXPECT_TRUE(albedo_only.albedo && !albedo_only.normal && !albedo_only.depth);
}

// The Cornell box, whose walls are seen through glass-free air at every
// distance: pools, schedules, the megakernel and two devices agree bit for bit.
TEST(Aovs, TheyHaveTheSameBytesOnAnyPoolScheduleAndDevices) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    RenderSettings settings;
    settings.spp = 4;
    settings.seed = 5;
    settings.aovs = kAll;
    settings.pool_size = 1200;
    const ImageSize size{40, 30};
    const FilmReadout reference = render_scene(test::cpu_device(), scene, *scene.camera, size, settings).film;
    auto agrees = [&](const FilmReadout& f) {
        return same_bytes(*f.albedo, *reference.albedo) && same_bytes(*f.normal, *reference.normal) &&
               same_bytes(*f.depth, *reference.depth);
    };
    settings.pool_size = 333;
    settings.schedule = Schedule::Refill;
    EXPECT_TRUE(agrees(render_scene(test::cpu_device(), scene, *scene.camera, size, settings).film));
    settings.integrator = Integrator::Megakernel;
    settings.schedule = Schedule::Auto;
    EXPECT_TRUE(agrees(render_scene(test::cpu_device(), scene, *scene.camera, size, settings).film));
    settings.integrator = Integrator::Wavefront;
    static const OpenClDevice second = open_device("cpu");
    Renderer two({&test::cpu_device(), &second}, scene, *scene.camera, size, settings);
    two.render_to(2);
    two.render_to(4);
    EXPECT_TRUE(agrees(two.read()));
}

} // namespace
} // namespace wf
