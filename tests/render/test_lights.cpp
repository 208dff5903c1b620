// test_lights.cpp — every kind of light through the whole renderer, against
// closed forms: an open floor lit by an environment (constant, and a map with
// a sun and a gradient), by a point light, an emissive square (plain, and
// under an emissive texture) and a directional light, under
// each --light-sampling technique. The floor is Lambertian (specular 0) and
// sees nothing but the light, so its radiance is albedo/π times its irradiance
// exactly: a biased MIS weight, a pdf off by a Jacobian, or a light-choice
// probability left out shows as a wrong image.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bvh/bvh_builder.h"
#include "scene/environment_map.h"
#include "image/error_metrics.h"
#include "render/renderer.h"
#include "support/statistics.h"
#include "support/test_support.h"

namespace wf {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kAlbedo = 0.5f;
constexpr uint32_t kSide = 32;

// A 200 × 200 floor at y = 0 facing up, seen from straight above with a narrow
// field, so every pixel sees the floor near its centre.
Scene open_floor() {
    Scene scene;
    test::add_quad(scene, {-100, 0, 100}, {100, 0, 100}, {100, 0, -100}, {-100, 0, -100},
                   test::add_material(scene, glm::vec3(kAlbedo), glm::vec3(0.0f), false));
    return scene;
}

SceneCamera above_floor() { return test::camera_looking({0, 1, 0}, {0, -1, 0}, {0, 0, -1}, 0.5f); }

RenderOutput render(const Scene& scene, uint32_t light_sampling, uint32_t spp, uint32_t max_depth) {
    RenderSettings settings;
    settings.spp = spp;
    settings.seed = 17;
    settings.light_sampling = light_sampling;
    settings.max_depth = max_depth;
    return render_scene(test::cpu_device(), scene, above_floor(), ImageSize{kSide, kSide}, settings);
}

// A readout that holds `value` in every pixel, exactly.
FilmReadout uniform_image(const FilmReadout& like, double value) {
    FilmReadout f = like;
    for (float& v : f.mean.rgb) v = float(value);
    for (float& v : f.variance_of_mean.rgb) v = 0.0f;
    return f;
}

const uint32_t kTechniques[] = {WF_LIGHT_SAMPLING_BSDF, WF_LIGHT_SAMPLING_NEE, WF_LIGHT_SAMPLING_MIS};
const char* const kTechniqueNames[] = {"bsdf", "nee", "mis"};

// Under a constant environment L the floor sees L over its whole upper
// hemisphere: radiance albedo · L.
TEST(Lights, ConstantEnvironmentLightsTheFloorByItsAlbedo) {
    Scene scene = open_floor();
    scene.environment = std::make_shared<EnvironmentMap>(constant_environment(2.0f));
    const double expected = kAlbedo * 2.0;
    for (int t = 0; t < 3; ++t) {
        const RenderOutput out = render(scene, kTechniques[t], 16, 1);
        EXPECT_EQ(out.summary.stats.nonfinite_samples, 0u);
        const double z = test::max_block_z(out.film, uniform_image(out.film, expected), 8);
        test::report_measured(std::string("constant environment, ") + kTechniqueNames[t] + ": mean " +
                              std::to_string(test::image_mean(out.film, 0).mean) + " (exact " +
                              std::to_string(expected) + "), max block |z| " + std::to_string(z));
        EXPECT_LT(z, test::bonferroni_threshold(0.01, 3 * 16 * 3)) << kTechniqueNames[t];
        EXPECT_NEAR(test::image_mean(out.film, 1).mean, expected, 1e-2 * expected) << kTechniqueNames[t];
    }
}

// An 8 × 4 map (rows on whole multiples of 45°, so the horizon is a row
// boundary) with a bright texel above the horizon, a gradient, and black
// texels. The floor's irradiance is the sum over texels of L ∫ cos θ dω, in
// closed form per row: Δφ (sin² θ_bottom − sin² θ_top) / 2 above the horizon.
// A directional light shares the light table, so the environment is chosen
// with probability below 1, which every density must include.
TEST(Lights, EnvironmentMapMatchesItsQuadratureUnderEveryTechnique) {
    Image image;
    image.width = 8;
    image.height = 4;
    image.rgb.assign(size_t{image.width} * image.height * 3, 0.0f);
    for (uint32_t row = 0; row < image.height; ++row)
        for (uint32_t col = 0; col < image.width; ++col) {
            float* p = &image.rgb[3 * (size_t{row} * image.width + col)];
            const float level = row == 1 && col == 5 ? 40.0f : (col % 3 == 0 ? 0.0f : 0.2f * float(col + row));
            p[0] = level;
            p[1] = 0.5f * level;
            p[2] = 0.25f * level + 0.1f;
        }
    Scene scene = open_floor();
    scene.environment = std::make_shared<EnvironmentMap>(make_environment(image, 1.5f, 30.0f, "test map"));
    PunctualLight sun{};
    sun.type = WF_PUNCTUAL_DIRECTIONAL;
    sun.direction[1] = -1.0f;
    for (float& i : sun.intensity) i = 20.0f; // about the environment's power: chosen half the time
    scene.punctual_lights.push_back(sun);

    glm::dvec3 irradiance(20.0); // the directional light's, at normal incidence
    for (uint32_t row = 0; row < image.height / 2; ++row) {
        const double top = kPi * row / image.height, bottom = kPi * (row + 1) / image.height;
        const double weight = (2.0 * kPi / image.width) *
                              0.5 * (std::sin(bottom) * std::sin(bottom) - std::sin(top) * std::sin(top));
        for (uint32_t col = 0; col < image.width; ++col)
            for (int c = 0; c < 3; ++c)
                irradiance[c] += 1.5 * weight * image.rgb[3 * (size_t{row} * image.width + col) + c];
    }
    for (int t = 0; t < 3; ++t) {
        const RenderOutput out = render(scene, kTechniques[t], 64, 1);
        EXPECT_EQ(out.summary.stats.nonfinite_samples, 0u);
        for (int c = 0; c < 3; ++c) {
            const double expected = kAlbedo / kPi * irradiance[c];
            const test::MeanWithError m = test::image_mean(out.film, c);
            if (c == 0)
                test::report_measured(std::string("environment map, ") + kTechniqueNames[t] + ": mean " +
                                      std::to_string(m.mean) + " ± " + std::to_string(m.standard_error) +
                                      ", quadrature " + std::to_string(expected));
            EXPECT_NEAR(m.mean, expected, 5.0 * m.standard_error) << kTechniqueNames[t] << ", channel " << c;
            EXPECT_LT(m.standard_error, 0.05 * expected) << kTechniqueNames[t]; // a bound with teeth
        }
    }
}

// A point light of intensity I at height h over the floor: E = I cos θ / r²
// = I h / r³ at each point; only next-event estimation can find it, so every
// technique must give the same closed form.
TEST(Lights, PointLightGivesInverseSquareIrradianceUnderEveryTechnique) {
    const float height = 0.6f, intensity = 5.0f;
    Scene scene = open_floor();
    PunctualLight light{};
    light.type = WF_PUNCTUAL_POINT;
    light.position[1] = height;
    light.position[0] = 0.1f;
    for (float& i : light.intensity) i = intensity;
    light.direction[2] = -1.0f;
    scene.punctual_lights.push_back(light);

    const SceneCamera camera = above_floor();
    for (int t = 0; t < 3; ++t) {
        const RenderOutput out = render(scene, kTechniques[t], 16, 1);
        EXPECT_EQ(out.summary.stats.nonfinite_samples, 0u);
        FilmReadout expected = out.film;
        // The pixel centre's ray meets the floor at (x, 0, z); image right is +x,
        // image up −z, at the camera's height 1 with half-angle 0.25 rad.
        const double half = std::tan(0.25);
        for (uint32_t j = 0; j < kSide; ++j)
            for (uint32_t i = 0; i < kSide; ++i) {
                const double x = half * (2.0 * (i + 0.5) / kSide - 1.0), z = half * (2.0 * (j + 0.5) / kSide - 1.0);
                const double dx = x - light.position[0], r2 = dx * dx + z * z + double(height) * height;
                const double value = kAlbedo / kPi * intensity * height / (r2 * std::sqrt(r2));
                for (int c = 0; c < 3; ++c) {
                    expected.mean.rgb[3 * (size_t{j} * kSide + i) + c] = float(value);
                    expected.variance_of_mean.rgb[3 * (size_t{j} * kSide + i) + c] = 0.0f;
                }
            }
        // The only randomness is where in its pixel each sample lands.
        const double error = compare_images(out.film.mean, expected.mean).relmse;
        test::report_measured(std::string("point light, ") + kTechniqueNames[t] + ": relMSE against the closed form " +
                              std::to_string(error));
        EXPECT_LT(error, 1e-4) << kTechniqueNames[t];
        (void)camera;
    }
}

// A square of radiance L facing down over the floor, off to the side of the
// camera's view: the floor's irradiance is Lambert's closed form for a
// polygon, E = L/2 Σ β_i (n · u_i), over its edges (β_i the angle the edge
// subtends at the point, u_i the unit normal of the plane through it and the
// point). Next-event estimation samples the square by area and converts to
// solid angle; BRDF sampling finds it by chance; MIS weighs the two: a pdf off
// by any factor, or a Jacobian left out, moves the NEE and MIS images off the
// closed form, and BRDF sampling checks the scene itself.
double square_irradiance(const glm::dvec3 corners[4], glm::dvec3 point, double radiance) {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 a = glm::normalize(corners[i] - point), b = glm::normalize(corners[(i + 1) % 4] - point);
        const double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
        sum += angle * glm::normalize(glm::cross(a, b)).y; // n = +y, the floor's
    }
    return radiance / 2.0 * std::fabs(sum);
}

// The floor under the square: each pixel's mean over a 4 x 4 grid of points
// of its footprint, where the camera's rays meet the floor (as in the point
// light's test).
FilmReadout square_image(const FilmReadout& like, const glm::dvec3 corners[4], double radiance) {
    FilmReadout expected = uniform_image(like, 0.0);
    const double half = std::tan(0.25);
    for (uint32_t j = 0; j < kSide; ++j)
        for (uint32_t i = 0; i < kSide; ++i) {
            double value = 0.0;
            for (int sj = 0; sj < 4; ++sj)
                for (int si = 0; si < 4; ++si) {
                    const double x = half * (2.0 * (i + (si + 0.5) / 4) / kSide - 1.0);
                    const double z = half * (2.0 * (j + (sj + 0.5) / 4) / kSide - 1.0);
                    value += kAlbedo / kPi * square_irradiance(corners, {x, 0.0, z}, radiance) / 16.0;
                }
            for (int c = 0; c < 3; ++c) expected.mean.rgb[3 * (size_t{j} * kSide + i) + c] = float(value);
        }
    return expected;
}

// The scene rendered with each technique (BRDF sampling at 1024 spp, the
// others at 64, one bounce) against square_image of `corners`, block by block
// and in the mean.
void expect_square_under_every_technique(const Scene& scene, const glm::dvec3 corners[4], double radiance,
                                         const std::string& what) {
    for (int t = 0; t < 3; ++t) {
        const RenderOutput out = render(scene, kTechniques[t], t == 0 ? 1024 : 64, 1);
        EXPECT_EQ(out.summary.stats.nonfinite_samples, 0u);
        const FilmReadout expected = square_image(out.film, corners, radiance);
        const double z = test::max_block_z(out.film, expected, 8);
        const double mean = test::image_mean(out.film, 1).mean, exact = test::image_mean(expected, 1).mean;
        test::report_measured(what + ", " + kTechniqueNames[t] + ": mean " + std::to_string(mean) +
                              " (closed form " + std::to_string(exact) + "), max block |z| " + std::to_string(z));
        EXPECT_LT(z, test::bonferroni_threshold(0.01, 3 * 16 * 3)) << what << ", " << kTechniqueNames[t];
        EXPECT_NEAR(mean, exact, 2e-2 * exact) << what << ", " << kTechniqueNames[t];
    }
}

TEST(Lights, EmissiveSquareGivesItsPolygonIrradianceUnderEveryTechnique) {
    const float radiance = 20.0f;
    const glm::vec3 corners[4] = {{0.15f, 0.5f, -0.15f}, {0.45f, 0.5f, -0.15f}, {0.45f, 0.5f, 0.15f},
                                  {0.15f, 0.5f, 0.15f}}; // counter-clockwise seen from below: it faces down
    Scene scene = open_floor();
    test::add_quad(scene, corners[0], corners[1], corners[2], corners[3],
                   test::add_material(scene, glm::vec3(0.0f), glm::vec3(radiance), false));
    const glm::dvec3 exact_corners[4] = {corners[0], corners[1], corners[2], corners[3]};
    expect_square_under_every_technique(scene, exact_corners, radiance, "emissive square");
}

// The same square, cut into 8 x 8 quads under an emissive texture of 8 x 8
// texels, each quad on one texel (nearest filtering): white in the four
// columns on the -x side, black in the rest. The light table leaves out the
// triangles whose texels are all black and keeps every one on white, and the
// floor sees the white half alone, as the closed form for that rectangle
// says, under every technique: a triangle on white left out would darken
// the NEE and MIS images, and BRDF sampling, which never reads the table,
// checks the scene.
TEST(Lights, TexturedEmitterIsChosenByItsTexelsUnderEveryTechnique) {
    constexpr uint32_t kCells = 8;
    const float radiance = 20.0f, x0 = 0.15f, z0 = -0.15f, side = 0.3f;
    Scene scene = open_floor();
    const uint32_t emitter = test::add_material(scene, glm::vec3(0.0f), glm::vec3(radiance), false);
    for (uint32_t row = 0; row < kCells; ++row)
        for (uint32_t col = 0; col < kCells; ++col) {
            const float xa = x0 + side * col / kCells, xb = x0 + side * (col + 1) / kCells;
            const float za = z0 + side * row / kCells, zb = z0 + side * (row + 1) / kCells;
            test::add_quad(scene, {xa, 0.5f, za}, {xb, 0.5f, za}, {xb, 0.5f, zb}, {xa, 0.5f, zb}, emitter); // faces down
        }
    // u along +x, v along +z over the square; the floor's corners read (0, 0).
    for (const glm::vec3& p : scene.positions)
        scene.uv0.push_back(p.y > 0.0f ? glm::vec2((p.x - x0) / side, (p.z - z0) / side) : glm::vec2(0.0f));
    scene.uv1 = scene.uv0;
    scene.tangents.assign(scene.positions.size(), glm::vec4(1, 0, 0, 1));
    DecodedImage half_white;
    half_white.width = half_white.height = kCells;
    half_white.channels = 3;
    for (uint32_t y = 0; y < kCells; ++y)
        for (uint32_t x = 0; x < kCells; ++x)
            half_white.texels.push_back(x < kCells / 2 ? pack_rgba8(255, 255, 255, 255) : pack_rgba8(0, 0, 0, 255));
    TextureInfo info{};
    info.offset = scene.textures.add_texels(half_white, "test");
    info.width = info.height = kCells;
    info.flags = WF_TEXTURE_SRGB | WF_TEXTURE_NEAREST;
    info.wrap_s = info.wrap_t = WF_WRAP_CLAMP_TO_EDGE;
    info.channels = 3;
    scene.materials[emitter].textures[WF_TEXTURE_EMISSIVE].texture = scene.textures.add_info(info, "half white");

    // Which triangles are lights: the square's are 2 to 129, two a quad, row by row.
    const Bvh bvh = build_bvh(scene.positions);
    const DeviceSceneData data = make_device_scene_data(scene, bvh);
    std::vector<bool> is_light(scene.triangle_count(), false);
    for (const LightEntry& light : data.lights)
        if (light.kind == WF_LIGHT_TRIANGLE) is_light[bvh.order[light.index]] = true;
    for (uint32_t t = 2; t < scene.triangle_count(); ++t) {
        const uint32_t col = (t - 2) / 2 % kCells;
        if (col < kCells / 2) EXPECT_TRUE(is_light[t]) << "triangle " << t << " on white";
        if (col >= kCells / 2 + 2) EXPECT_FALSE(is_light[t]) << "triangle " << t << " two texels clear of white";
    }

    const glm::dvec3 white[4] = {{x0, 0.5, z0}, {x0 + side / 2, 0.5, z0}, {x0 + side / 2, 0.5, z0 + side},
                                 {x0, 0.5, z0 + side}};
    expect_square_under_every_technique(scene, white, radiance, "textured emitter");
}

// A directional light of illuminance E at 60° from the zenith: E cos 60° on
// the floor, the same in every pixel and every sample.
TEST(Lights, DirectionalLightGivesCosineIrradiance) {
    Scene scene = open_floor();
    PunctualLight light{};
    light.type = WF_PUNCTUAL_DIRECTIONAL;
    const float angle = float(kPi / 3.0);
    light.direction[0] = std::sin(angle);
    light.direction[1] = -std::cos(angle); // the way the light travels
    for (float& i : light.intensity) i = 3.0f;
    scene.punctual_lights.push_back(light);
    const double expected = kAlbedo / kPi * 3.0 * std::cos(angle);
    for (int t = 0; t < 3; ++t) {
        const RenderOutput out = render(scene, kTechniques[t], 4, 1);
        for (float v : out.film.mean.rgb) ASSERT_NEAR(v, expected, 1e-5 * expected) << kTechniqueNames[t];
    }
}

// The floor shadows nothing, but a wall between the floor and a directional
// light must: the shadow ray toward infinity has to leave the scene's bounds.
TEST(Lights, DirectionalLightIsShadowedByAWall) {
    Scene scene = open_floor();
    // A roof at y = 0.5 facing down covers everything the camera sees.
    test::add_quad(scene, {-5, 0.5f, -5}, {5, 0.5f, -5}, {5, 0.5f, 5}, {-5, 0.5f, 5},
                   test::add_material(scene, glm::vec3(0.0f), glm::vec3(0.0f), false));
    PunctualLight light{};
    light.type = WF_PUNCTUAL_DIRECTIONAL;
    light.direction[1] = -1.0f;
    for (float& i : light.intensity) i = 3.0f;
    scene.punctual_lights.push_back(light);
    SceneCamera camera = test::camera_looking({0, 0.3f, 0}, {0, -1, 0}, {0, 0, -1}, 0.5f);
    RenderSettings settings;
    settings.spp = 4;
    settings.max_depth = 1;
    const RenderOutput out = render_scene(test::cpu_device(), scene, camera, ImageSize{8, 8}, settings);
    for (float v : out.film.mean.rgb) ASSERT_EQ(v, 0.0f);
}

TEST(Lights, AnUnlitSceneGetsAWhiteEnvironmentAndSaysSo) {
    Scene scene = open_floor();
    light_unlit_scene(scene);
    ASSERT_TRUE(scene.environment);
    ASSERT_FALSE(scene.warnings.empty());
    EXPECT_NE(scene.warnings.back().find("no light"), std::string::npos);
    const RenderOutput out = render(scene, WF_LIGHT_SAMPLING_MIS, 8, WF_UNLIMITED_DEPTH);
    EXPECT_NEAR(test::image_mean(out.film, 0).mean, kAlbedo, 0.02);

    Scene lit = open_floor();
    lit.materials[0].emission = glm::vec3(1.0f);
    light_unlit_scene(lit);
    EXPECT_FALSE(lit.environment); // an emissive triangle is light enough
    EXPECT_TRUE(lit.warnings.empty());
}

} // namespace
} // namespace wf
