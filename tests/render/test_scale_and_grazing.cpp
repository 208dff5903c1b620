// test_scale_and_grazing.cpp — two cases that break renderers with a fixed
// epsilon in their ray offsets.
//
// Scale: the Cornell box shrunk by 1e-4, grown by 1e5, and moved 1e5 along x
// must render the same image as at scale 1 (radiance does not depend on
// units). A fixed offset is too large for the small box (light leaks at its
// corners, where walls are closer than the offset) and too small for the
// large or far one (surfaces shadow themselves).
//
// Grazing: a floor lit by a rectangle about 1° above its horizon. Every shadow
// ray leaves the floor almost parallel to it, which is where an offset that
// does not scale with the hit point's error lets a ray re-hit its own surface
// and turns a pixel black ("shadow acne"). The scene is turned and moved off
// the axes, so hit points carry rounding error (on the plane y = 0 they would
// be exact). The radiance must match the analytic point-to-rectangle form
// factor in every pixel.
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include "gltf/gltf_loader.h"
#include "render/renderer.h"
#include "support/statistics.h"
#include "support/test_support.h"

namespace wf {
namespace {

Scene transformed(Scene scene, float scale, glm::vec3 offset) {
    for (glm::vec3& p : scene.positions) p = scale * p + offset;
    scene.camera->position = scale * scene.camera->position + offset;
    return scene;
}

// The scene and camera under a rotation and a translation: no image changes.
void move_rigidly(Scene& scene, SceneCamera& camera, const glm::mat3& rotation, glm::vec3 offset) {
    for (glm::vec3& p : scene.positions) p = rotation * p + offset;
    for (glm::vec3& n : scene.normals) n = rotation * n;
    camera.position = rotation * camera.position + offset;
    camera.forward = rotation * camera.forward;
    camera.up = rotation * camera.up;
}

FilmReadout render(const Scene& scene, uint32_t seed) {
    RenderSettings settings;
    settings.spp = 256;
    settings.seed = seed;
    const RenderOutput out = render_scene(test::cpu_device(), scene, *scene.camera, ImageSize{32, 32}, settings);
    EXPECT_EQ(out.summary.stats.nonfinite_samples, 0u);
    return out.film;
}

TEST(Scale, CornellBoxLooksTheSameAtAnyScaleAndPlace) {
    const Scene base = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    const FilmReadout reference = render(base, 1);
    struct Case {
        const char* name;
        float scale;
        glm::vec3 offset;
    };
    const Case cases[] = {{"shrunk by 1e-4", 1e-4f, glm::vec3(0.0f)},
                          {"grown by 1e5", 1e5f, glm::vec3(0.0f)},
                          {"moved 1e5 along x", 1.0f, glm::vec3(1e5f, 0.0f, 0.0f)}};
    // 3 cases × 16 blocks × 3 channels, 1% family-wise.
    const double threshold = test::bonferroni_threshold(0.01, 3 * 16 * 3);
    for (const Case& c : cases) {
        const double z = test::max_block_z(render(transformed(base, c.scale, c.offset), 2), reference, 8);
        test::report_measured(std::string("Cornell box ") + c.name + ": max 8x8-block |z| " + std::to_string(z) +
                              " (bound " + std::to_string(threshold) + ")");
        EXPECT_LT(z, threshold) << c.name;
    }
}

// The form factor from a point to an axis-aligned rectangle in a parallel
// plane at height h (see test_physics.cpp for the derivation by corners).
double corner_form_factor(double a, double b, double h) {
    const double x = a / h, y = b / h;
    const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * 3.14159265358979323846);
}

TEST(Grazing, FloorLitNearItsHorizonHasNoShadowAcne) {
    const float albedo = 0.5f, radiance = 100.0f, height = 0.05f, centre = 3.0f;
    Scene scene;
    const uint32_t floor = test::add_material(scene, glm::vec3(albedo), glm::vec3(0.0f), false);
    const uint32_t light = test::add_material(scene, glm::vec3(0.0f), glm::vec3(radiance), false);
    test::add_quad(scene, {-50, 0, 50}, {50, 0, 50}, {50, 0, -50}, {-50, 0, -50}, floor);
    test::add_quad(scene, {-0.5f, height, -0.5f}, {0.5f, height, -0.5f}, {0.5f, height, 0.5f}, {-0.5f, height, 0.5f},
                   light);
    // Looking straight down at the floor square x ∈ [2.5, 3.5], z ∈ [−0.5, 0.5];
    // from there the light is 0.8° to 1.1° above the horizon.
    SceneCamera camera;
    camera.position = {centre, 0.5f, 0.0f};
    camera.forward = {0, -1, 0};
    camera.up = {0, 0, 1};
    camera.vertical_fov = float(3.14159265358979323846 / 2);
    const glm::mat3 rotation(glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f))));
    move_rigidly(scene, camera, rotation, {103.7f, -41.3f, 259.1f});
    RenderSettings settings;
    settings.spp = 64;
    settings.max_depth = 1;
    const uint32_t n = 32;
    const RenderOutput out = render_scene(test::cpu_device(), scene, camera, ImageSize{n, n}, settings);
    ASSERT_EQ(out.summary.stats.nonfinite_samples, 0u);

    // Image right is world −x, image up world +z (as in test_physics.cpp).
    FilmReadout expected = out.film;
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            const double px = centre - 0.5 * (2.0 * (i + 0.5) / n - 1.0), pz = 0.5 * (1.0 - 2.0 * (j + 0.5) / n);
            const double f = corner_form_factor(0.5 - px, 0.5 - pz, height) - corner_form_factor(-0.5 - px, 0.5 - pz, height) -
                             corner_form_factor(0.5 - px, -0.5 - pz, height) + corner_form_factor(-0.5 - px, -0.5 - pz, height);
            const size_t p = size_t{j} * n + i;
            for (int c = 0; c < 3; ++c) {
                expected.mean.rgb[3 * p + c] = static_cast<float>(albedo * radiance * f);
                expected.variance_of_mean.rgb[3 * p + c] = 0.0f;
                // No speckles: acne would leave pixels far below their value.
                ASSERT_GT(out.film.mean.rgb[3 * p + c], 0.5 * albedo * radiance * f) << "pixel " << i << ", " << j;
            }
        }
    const double z = test::max_block_z(out.film, expected, 8), bound = test::bonferroni_threshold(0.01, 16 * 3);
    test::report_measured("grazing floor against the analytic form factor: max 8x8-block |z| " +
                          std::to_string(z) + " (bound " + std::to_string(bound) + ")");
    EXPECT_LT(z, bound);
}

} // namespace
} // namespace wf
