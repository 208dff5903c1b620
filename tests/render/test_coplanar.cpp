// test_coplanar.cpp — an emitter set in a larger surface, exactly coplanar with
// it or standing off it by 1e-6 of the scene's size, is seen whole: with no
// bounce, every pixel that sees only the emitter holds exactly its radiance and
// every pixel that sees only the surface holds exactly 0, with no pixel
// flickering to the other surface as the roundings of the two hits fall (the
// rule of kernels/geometry/bvh_traverse.h). The standoff changes nothing.
//
// The corners are whole numbers, so "exactly coplanar" is exact in float, for
// a plane in an axis plane and for one tilted off every axis. Either quad may
// come first in the scene, so no rule by triangle index alone can pass.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "render/renderer.h"
#include "support/test_support.h"

namespace wf {
namespace {

// The surface is center ± 2u ± 2w, the emitter center ± u ± w; u ⟂ w.
struct CoplanarCase {
    std::string name;
    glm::vec3 center, u, w;
};

const glm::vec3 kRadiance(3.0f, 5.0f, 7.0f);
constexpr uint32_t kSize = 64;

// The quad center ± u ± w with its front face towards +(u × w).
void add_centered_quad(Scene& scene, glm::vec3 center, glm::vec3 u, glm::vec3 w, uint32_t material) {
    test::add_quad(scene, center - u - w, center + u - w, center + u + w, center - u + w, material);
}

// Renders the pair with the emitter moved off the surface, towards the camera,
// by `standoff` times the scene's size; the camera looks straight at it along
// the normal, with up along w, and sees a square of side 4|w|.
Image render_pair(const CoplanarCase& c, float standoff, bool emitter_first) {
    Scene scene;
    const uint32_t surface = test::add_material(scene, glm::vec3(0.5f), glm::vec3(0.0f), false);
    const uint32_t emitter = test::add_material(scene, glm::vec3(0.0f), kRadiance, false);
    const glm::vec3 normal = glm::normalize(glm::cross(c.u, c.w));
    const float size = 4.0f * glm::max(glm::length(c.u), glm::length(c.w));
    const glm::vec3 lifted = c.center + standoff * size * normal;
    if (emitter_first) add_centered_quad(scene, lifted, c.u, c.w, emitter);
    add_centered_quad(scene, c.center, 2.0f * c.u, 2.0f * c.w, surface);
    if (!emitter_first) add_centered_quad(scene, lifted, c.u, c.w, emitter);

    SceneCamera camera;
    const float distance = 1.5f * size;
    camera.position = c.center + distance * normal;
    camera.forward = -normal;
    camera.up = glm::normalize(c.w);
    camera.vertical_fov = 2.0f * std::atan(2.0f * glm::length(c.w) / distance);
    RenderSettings settings;
    settings.spp = 16;
    settings.max_depth = 0;
    const RenderOutput out = render_scene(test::cpu_device(), scene, camera, ImageSize{kSize, kSize}, settings);
    EXPECT_EQ(out.summary.stats.nonfinite_samples, 0u);
    return out.film.mean;
}

// Pixels whose whole square sees the emitter hold its radiance; those whose
// square sees none of it, 0. The image is symmetric about its centre, so the
// signs of the camera's axes do not matter.
void expect_emitter_seen_whole(const CoplanarCase& c, const Image& image, const std::string& what) {
    const float half_side = 2.0f * glm::length(c.w);  // of the square the image sees
    const float pixel = 2.0f * half_side / kSize;     // a pixel's side, in the plane
    const float half_x = glm::length(c.u), half_y = glm::length(c.w);
    int wrong = 0, inside = 0, outside = 0;
    for (uint32_t j = 0; j < kSize; ++j) {
        for (uint32_t i = 0; i < kSize; ++i) {
            const float x = std::abs((2.0f * (i + 0.5f) / kSize - 1.0f) * half_side);
            const float y = std::abs((2.0f * (j + 0.5f) / kSize - 1.0f) * half_side);
            const bool in = x < half_x - pixel && y < half_y - pixel;
            const bool out = x > half_x + pixel || y > half_y + pixel;
            for (int k = 0; k < 3; ++k) {
                const float v = image.rgb[3 * (j * kSize + i) + k];
                if (!std::isfinite(v) || (in && v != kRadiance[k]) || (out && v != 0.0f)) {
                    if (++wrong <= 5)
                        ADD_FAILURE() << what << ": pixel (" << i << ", " << j << ") channel " << k << " is " << v;
                }
            }
            inside += in;
            outside += out;
        }
    }
    test::report_measured(what + ": " + std::to_string(wrong) + " wrong of " + std::to_string(inside) +
                          " emitter and " + std::to_string(outside) + " surface pixels");
    EXPECT_EQ(wrong, 0) << what;
    EXPECT_GT(inside, 300) << what; // both kinds of pixel are well represented
    EXPECT_GT(outside, 1000) << what;
}

TEST(Coplanar, EmitterInItsSurfaceIsSeenWhole) {
    const CoplanarCase cases[] = {
        {"in an axis plane", glm::vec3(3.0f, -5.0f, 0.75f), glm::vec3(8.0f, 0.0f, 0.0f), glm::vec3(0.0f, 8.0f, 0.0f)},
        // In the plane x + 2y + 3z = 12, off every axis: (2, -1, 0) and (3, 6, -5)
        // are orthogonal and lie in it.
        {"tilted", glm::vec3(11.0f, -7.0f, 5.0f), glm::vec3(14.0f, -7.0f, 0.0f), glm::vec3(6.0f, 12.0f, -10.0f)}};
    for (const CoplanarCase& c : cases) {
        for (bool emitter_first : {true, false}) {
            const std::string what = c.name + (emitter_first ? ", emitter first" : ", emitter last");
            const Image touching = render_pair(c, 0.0f, emitter_first);
            expect_emitter_seen_whole(c, touching, what + ", coplanar");
            const Image apart = render_pair(c, 1e-6f, emitter_first);
            expect_emitter_seen_whole(c, apart, what + ", 1e-6 apart");
            size_t changed = 0;
            for (size_t k = 0; k < touching.rgb.size(); ++k) changed += touching.rgb[k] != apart.rgb[k];
            EXPECT_EQ(changed, 0u) << what << ": values the standoff changed";
        }
    }
}

} // namespace
} // namespace wf
