// test_furnace.cpp — the white furnace through the whole renderer on the
// device: a sphere of radius 1 (64 x 128 segments, smooth normals), base
// colour 1, under a uniform environment of radiance 1, unlimited depth. A
// material that absorbs nothing returns 1 at every pixel, the rim included;
// the energy compensation of kernels/bsdf/albedo.h is what makes glTF's
// dielectric and metal do so. Before it they returned 0.86-0.92 (dielectric)
// and 0.41-0.88 (metal) over the sphere, down to 0.57 at the rim.
//
// Two views: the whole sphere, and a narrow one along its limb, where view
// cosines below 0.2 fill the image instead of a pixel-wide ring. Only pixels
// whose corner rays all hit the sphere are counted; each mean has its
// standard error from the film's variance, so the bound is 0.01 + 3 sigma.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "render/renderer.h"
#include "scene/environment_map.h"
#include "support/test_support.h"

namespace wf {
namespace {

// The direction of the camera ray through image point (x, y) in [0, 1]^2, as
// kernels/stages/camera_ray.inc computes it.
glm::vec3 camera_ray(const SceneCamera& c, ImageSize size, float x, float y) {
    const glm::vec3 forward = glm::normalize(c.forward);
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float t = std::tan(0.5f * c.vertical_fov), aspect = float(size.width) / float(size.height);
    return glm::normalize(forward + (2.0f * x - 1.0f) * t * aspect * right + (1.0f - 2.0f * y) * t * up);
}

// The cosine between the unit sphere's normal and the way back along the ray,
// or -1 where the ray misses it.
float view_cosine(glm::vec3 origin, glm::vec3 direction) {
    const float b = glm::dot(origin, direction);
    const float disc = b * b - (glm::dot(origin, origin) - 1.0f);
    if (disc <= 0.0f) return -1.0f;
    const glm::vec3 hit = origin + (-b - std::sqrt(disc)) * direction;
    return -glm::dot(glm::normalize(hit), direction);
}

struct Region {
    double mean = 0.0, standard_error = 0.0;
    size_t pixels = 0;
};

// The mean luminance of the pixels wholly on the sphere whose centre's view
// cosine is below `max_cosine`.
Region measure(const FilmReadout& film, const SceneCamera& camera, ImageSize size, float max_cosine) {
    double sum = 0.0, variance = 0.0;
    size_t n = 0;
    for (uint32_t py = 0; py < size.height; ++py)
        for (uint32_t px = 0; px < size.width; ++px) {
            bool inside = true;
            for (int corner = 0; corner < 4 && inside; ++corner) {
                const float x = (px + float(corner & 1)) / size.width, y = (py + float(corner >> 1)) / size.height;
                inside = view_cosine(camera.position, camera_ray(camera, size, x, y)) > 0.0f;
            }
            const float cosine =
                view_cosine(camera.position, camera_ray(camera, size, (px + 0.5f) / size.width, (py + 0.5f) / size.height));
            if (!inside || cosine >= max_cosine) continue;
            const size_t i = 3 * (size_t(py) * size.width + px);
            const float* rgb = &film.mean.rgb[i];
            const float* var = &film.variance_of_mean.rgb[i];
            sum += (rgb[0] + rgb[1] + rgb[2]) / 3.0;
            variance += std::max({var[0], var[1], var[2]}); // the channels of one path move together
            ++n;
        }
    Region r;
    r.pixels = n;
    if (n) {
        r.mean = sum / n;
        r.standard_error = std::sqrt(variance) / n;
    }
    return r;
}

struct Case {
    const char* name;
    float metallic, roughness;
    float clearcoat = 0.0f, clearcoat_roughness = 0.0f; // KHR_materials_clearcoat over the rest
    float sheen = 0.0f, sheen_roughness = 0.0f;         // a white KHR_materials_sheen of this much
};

class WhiteFurnace : public ::testing::TestWithParam<Case> {};

TEST_P(WhiteFurnace, ASphereReturnsTheSkyEverywhereTheRimIncluded) {
    const Case c = GetParam();
    Scene scene;
    const uint32_t m = test::add_material(scene, glm::vec3(1.0f), glm::vec3(0.0f), false);
    scene.materials[m].metallic = c.metallic;
    scene.materials[m].roughness = c.roughness;
    scene.materials[m].specular = 1.0f; // glTF's default: the dielectric has its specular layer
    scene.materials[m].clearcoat = c.clearcoat;
    scene.materials[m].clearcoat_roughness = c.clearcoat_roughness;
    scene.materials[m].sheen_color = glm::vec3(c.sheen);
    scene.materials[m].sheen_roughness = c.sheen_roughness;
    test::add_smooth_sphere(scene, m);
    scene.environment = std::make_shared<EnvironmentMap>(constant_environment(1.0f));

    RenderSettings settings;
    settings.max_depth = WF_UNLIMITED_DEPTH; // every bounce counts where energy is measured
    settings.spp = 32;
    settings.seed = 7;
    // The whole sphere, and the limb seen through a narrow lens: the view
    // from (0, 0, 4) grazes the sphere 14.48 degrees off its centre.
    const SceneCamera whole = test::camera_looking({0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 0.55f);
    const glm::vec3 limb_direction(std::sin(0.2505f), 0.0f, -std::cos(0.2505f));
    const SceneCamera limb = test::camera_looking({0, 0, 4}, limb_direction, {0, 1, 0}, 0.02f);
    const ImageSize size{64, 64};
    const FilmReadout whole_film = render_scene(test::cpu_device(), scene, whole, size, settings).film;
    const FilmReadout limb_film = render_scene(test::cpu_device(), scene, limb, size, settings).film;

    const Region sphere = measure(whole_film, whole, size, 2.0f);
    const Region rim = measure(limb_film, limb, size, 0.2f);
    char line[160];
    std::snprintf(line, sizeof line, "furnace %-22s sphere %.4f ± %.4f (%zu px), rim %.4f ± %.4f (%zu px)", c.name,
                  sphere.mean, sphere.standard_error, sphere.pixels, rim.mean, rim.standard_error, rim.pixels);
    test::report_measured(line);
    ASSERT_GT(sphere.pixels, 1500u);
    ASSERT_GT(rim.pixels, 500u);
    EXPECT_NEAR(sphere.mean, 1.0, 0.01 + 3.0 * sphere.standard_error);
    EXPECT_NEAR(rim.mean, 1.0, 0.01 + 3.0 * rim.standard_error);
}

INSTANTIATE_TEST_SUITE_P(Materials, WhiteFurnace,
                         ::testing::Values(Case{"dielectric_r0.05", 0.0f, 0.05f}, Case{"dielectric_r0.25", 0.0f, 0.25f},
                                           Case{"dielectric_r0.5", 0.0f, 0.5f}, Case{"dielectric_r1", 0.0f, 1.0f},
                                           Case{"metal_r0.1", 1.0f, 0.1f}, Case{"metal_r0.25", 1.0f, 0.25f}, Case{"metal_r0.5", 1.0f, 0.5f},
                                           Case{"metal_r1", 1.0f, 1.0f},
                                           Case{"coat_r0_over_dielectric_r0.5", 0.0f, 0.5f, 1.0f, 0.0f},
                                           Case{"coat_r0.5_over_metal_r0.25", 1.0f, 0.25f, 1.0f, 0.5f},
                                           Case{"sheen_r0.3_over_dielectric_r0.5", 0.0f, 0.5f, 0.0f, 0.0f, 1.0f, 0.3f}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             std::string name = info.param.name;
                             for (char& ch : name)
                                 if (ch == '.') ch = '_';
                             return name;
                         });

} // namespace
} // namespace wf
