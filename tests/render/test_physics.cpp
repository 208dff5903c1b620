// test_physics.cpp — renders whose answer is known in closed form.
//
// Furnace: inside a closed box whose walls emit Le and reflect with albedo ρ,
// radiance is Le / (1 − ρ) in every direction. The render runs every stage,
// roulette included, and must agree within a bound from its own sample spread;
// so must it when roulette's survival is capped below ρ (--roulette-cap),
// which ends paths sooner but adds no bias.
//
// Next-event estimation: a Lambertian floor under a rectangular emitter
// parallel to it. Direct radiance at a floor point is ρ · Le · F, with F the
// analytic form factor from the point to the rectangle.
#include <cmath>

#include <gtest/gtest.h>

#include "gltf/gltf_loader.h"
#include "render/renderer.h"
#include "support/test_support.h"

namespace wf {
namespace {

constexpr double kPi = 3.14159265358979323846;


// Renders the furnace of albedo `albedo` (emission 1) and checks the image
// mean, and unless the weights are heavy-tailed every pixel, against
// 1 / (1 − ρ); returns the mean closest-hit rays a sample.
double expect_furnace_radiance(float albedo, RenderSettings settings, bool heavy_tailed = false) {
    const float emission = 1.0f;
    const Scene scene = test::furnace_box(albedo, emission);
    settings.max_depth = WF_UNLIMITED_DEPTH; // a bound would cut ρ^256 of the answer: 8% at ρ = 0.99
    settings.spp = 64;
    settings.seed = 7;
    const RenderOutput out = render_scene(test::cpu_device(), scene,
                                          test::camera_looking(glm::vec3(0.1f, -0.2f, 0.3f), {0, 0, -1}, {0, 1, 0}, 1.2f),
                                          ImageSize{48, 48}, settings);
    EXPECT_EQ(out.summary.stats.nonfinite_samples, 0u);
    EXPECT_EQ(out.summary.stats.samples, 48u * 48u * 64u);
    const double expected = emission / (1.0 - albedo);
    const size_t pixels = 48 * 48;
    for (int c = 0; c < 3; ++c) {
        const test::ChannelStats s = test::channel_stats(out.film.mean, c);
        // The pixels are independent estimates of one value: their mean lies
        // within 4 standard errors of it, and each pixel within 5.5 spreads
        // (a two-sided 5.5σ tail over 2304 pixels fails with probability < 1e-4).
        EXPECT_NEAR(s.mean, expected, 4.0 * s.stddev / std::sqrt(double(pixels))) << "channel " << c;
        for (size_t p = 0; p < pixels && !heavy_tailed; ++p)
            if (std::fabs(out.film.mean.rgb[3 * p + c] - expected) > 5.5 * s.stddev) {
                ADD_FAILURE() << "pixel " << p << " channel " << c << ": " << out.film.mean.rgb[3 * p + c];
                break;
            }
    }
    return double(out.summary.stats.closest_rays) / out.summary.stats.samples;
}

class Furnace : public ::testing::TestWithParam<float> {};

TEST_P(Furnace, EveryPixelSeesEmissionOverOneMinusAlbedo) {
    const float albedo = GetParam();
    // Roulette must be what ends these paths: mean length near 1 / (1 − ρ).
    // By default it starts at the fifth bounce, where a path of ρ = 0.5 survives
    // with ρ^5 = 1/32 and then weighs 32 times more: a few pixels stand out, so
    // only the mean is checked there. From the first bounce each step survives
    // with ρ and weighs 1/ρ more, and every pixel keeps within the bound.
    EXPECT_GT(expect_furnace_radiance(albedo, RenderSettings{}, true), 0.8 / (1.0 - albedo));
    RenderSettings early;
    early.roulette_depth = 1;
    EXPECT_GT(expect_furnace_radiance(albedo, early), 0.8 / (1.0 - albedo));
}

// Survival capped at 0.85 from the first bounce, under ρ = 0.9: each bounce
// then survives with 0.85 (1 / 0.15 = 6.7 segments, against 10 uncapped). The
// weights grow by 0.9 / 0.85 a bounce: of finite variance (ρ² / 0.85 < 1) but
// heavy-tailed (a pixel of 32 among 10s was seen), so only the mean is checked.
TEST(Furnace, RouletteCappedBelowTheAlbedoEndsPathsSoonerWithoutBias) {
    RenderSettings settings;
    settings.roulette_depth = 1;
    settings.roulette_cap = 0.85f;
    const double mean_path = expect_furnace_radiance(0.9f, settings, true);
    test::report_measured("furnace of albedo 0.9, survival at most 0.85: " + std::to_string(mean_path) +
                          " segments a sample");
    EXPECT_NEAR(mean_path, 1.0 / 0.15, 0.2);
}

INSTANTIATE_TEST_SUITE_P(Albedo, Furnace, ::testing::Values(0.5f, 0.9f));

// No path decides how long a render takes: by default a path ends after
// kDefaultMaxDepth bounces even where roulette would let it go on (here a
// furnace of albedo 0.9999, where it survives ~10^4 bounces); unlimited, as
// asked for, it goes on.
TEST(Furnace, PathsEndAtTheDefaultBoundAndGoOnWhenUnlimited) {
    const Scene scene = test::furnace_box(0.9999f, 1.0f);
    const SceneCamera camera = test::camera_looking(glm::vec3(0.0f), {0, 0, -1}, {0, 1, 0}, 1.2f);
    const auto longest_bounces = [&](uint32_t max_depth) {
        RenderSettings settings;
        if (max_depth) settings.max_depth = max_depth;
        settings.spp = 4;
        const RenderOutput out = render_scene(test::cpu_device(), scene, camera, ImageSize{8, 8}, settings);
        // Buckets 0, 1, 2-3, 4-7, ...: bucket b >= 1 starts at 2^(b-1) bounces.
        const auto& lengths = out.summary.stats.path_lengths;
        size_t last = 0;
        for (size_t b = 0; b < lengths.size(); ++b)
            if (lengths[b]) last = b;
        return last == 0 ? 0u : 1u << (last - 1);
    };
    EXPECT_EQ(longest_bounces(0), kDefaultMaxDepth);
    EXPECT_GE(longest_bounces(WF_UNLIMITED_DEPTH), 2048u);
}

// With no bounce, a pixel that sees only the light holds exactly its radiance,
// and a pixel that sees a wall holds exactly nothing.
TEST(Emission, SeenDirectlyTheLightIsExactlyItsRadiance) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    RenderSettings settings;
    settings.spp = 16;
    settings.max_depth = 0;
    const uint32_t n = 64;
    const RenderOutput out = render_scene(test::cpu_device(), scene, *scene.camera, ImageSize{n, n}, settings);
    glm::vec3 le(0.0f);
    for (const SceneMaterial& m : scene.materials) le = glm::max(le, m.emission);
    // The light's centre projects to column 32, row 9 of 64; it spans about ±5 columns.
    for (uint32_t x : {30u, 32u, 34u})
        for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(out.film.mean.rgb[3 * (9 * n + x) + c], le[c]) << x;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(out.film.mean.rgb[3 * (40 * n + 32) + c], 0.0f); // the back wall
}

// A single-sided emitter is dark from behind; a double-sided one is not.
TEST(Emission, LeavesTheFrontFaceUnlessDoubleSided) {
    for (bool double_sided : {false, true}) {
        Scene scene;
        const uint32_t m = test::add_material(scene, glm::vec3(0.0f), glm::vec3(2.0f, 3.0f, 4.0f), double_sided);
        test::add_quad(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, m); // faces +z
        RenderSettings settings;
        settings.spp = 4;
        for (float side : {1.0f, -1.0f}) {
            const RenderOutput out = render_scene(
                test::cpu_device(), scene, test::camera_looking({0, 0, 3 * side}, {0, 0, -side}, {0, 1, 0}, 0.3f),
                ImageSize{8, 8}, settings);
            const bool lit = side > 0.0f || double_sided;
            EXPECT_FLOAT_EQ(out.film.mean.rgb[3 * (4 * 8 + 4) + 2], lit ? 4.0f : 0.0f)
                << (double_sided ? "double-sided" : "single-sided") << ", seen from " << (side > 0 ? "front" : "back");
        }
    }
}

// The per-bounce layers split the image without losing or adding light: they
// sum to it, and in the Cornell box the light seen directly is bounce 0 alone.
TEST(BounceLayers, SumToTheImage) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    RenderSettings settings;
    settings.spp = 8;
    settings.bounce_layers = 4;
    const RenderOutput out = render_scene(test::cpu_device(), scene, *scene.camera, ImageSize{32, 32}, settings);
    ASSERT_EQ(out.film.bounce_layers.size(), 4u);
    double image = 0.0, layers = 0.0, layer_energy[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < out.film.mean.rgb.size(); ++i) {
        image += out.film.mean.rgb[i];
        for (int l = 0; l < 4; ++l) {
            layers += out.film.bounce_layers[l].rgb[i];
            layer_energy[l] += out.film.bounce_layers[l].rgb[i];
        }
    }
    EXPECT_NEAR(layers, image, 1e-5 * image);
    for (int l = 0; l < 4; ++l) EXPECT_GT(layer_energy[l], 0.0) << "layer " << l;
    // Row 4 of 32 sees the light: there bounce 0 is the light's radiance plus nothing else of note.
    const size_t light_pixel = 3 * (4 * 32 + 16);
    EXPECT_GT(out.film.bounce_layers[0].rgb[light_pixel], 0.9f * out.film.mean.rgb[light_pixel]);
}

// Form factor from a point on a plane to the rectangle [0,a]×[0,b] of a parallel
// plane at height h, one corner straight above the point; odd in a and in b, so
// any axis-aligned rectangle follows by inclusion–exclusion of its corners.
double corner_form_factor(double a, double b, double h) {
    const double x = a / h, y = b / h;
    const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * kPi);
}

double rectangle_form_factor(double px, double pz, double x0, double x1, double z0, double z1, double h) {
    return corner_form_factor(x1 - px, z1 - pz, h) - corner_form_factor(x0 - px, z1 - pz, h) -
           corner_form_factor(x1 - px, z0 - pz, h) + corner_form_factor(x0 - px, z0 - pz, h);
}

class NextEventEstimation : public ::testing::TestWithParam<uint32_t> {};

TEST_P(NextEventEstimation, FloorUnderRectangleMatchesFormFactor) {
    const uint32_t max_depth = GetParam();
    const float albedo = 0.5f, radiance = 10.0f, height = 1.0f;
    const float x0 = -0.5f, x1 = 0.5f, z0 = -0.25f, z1 = 0.75f;
    Scene scene;
    const uint32_t floor = test::add_material(scene, glm::vec3(albedo), glm::vec3(0.0f), false);
    const uint32_t light = test::add_material(scene, glm::vec3(0.0f), glm::vec3(radiance), false);
    test::add_quad(scene, {-50, 0, 50}, {50, 0, 50}, {50, 0, -50}, {-50, 0, -50}, floor);   // faces +y
    test::add_quad(scene, {x0, height, z0}, {x1, height, z0}, {x1, height, z1}, {x0, height, z1}, light); // faces −y
    ASSERT_LT(glm::cross(scene.positions[7] - scene.positions[6], scene.positions[8] - scene.positions[6]).y, 0.0f);

    // Looking straight down from half the light's height: a 90° field of view
    // spans the floor square [−0.5, 0.5]², and the camera never sees the light.
    const uint32_t n = 64;
    RenderSettings settings;
    settings.spp = 64;
    settings.max_depth = max_depth;
    const RenderOutput out = render_scene(test::cpu_device(), scene,
                                          test::camera_looking({0, 0.5f, 0}, {0, -1, 0}, {0, 0, 1}, float(kPi / 2)),
                                          ImageSize{n, n}, settings);
    ASSERT_EQ(out.summary.stats.nonfinite_samples, 0u);

    // Image right is world −x, image up is world +z; the floor point of pixel
    // (i, j)'s centre is at 0.5 · the camera-plane offsets.
    std::vector<double> ratio(n * n);
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            const double sx = 2.0 * (i + 0.5) / n - 1.0, sy = 1.0 - 2.0 * (j + 0.5) / n;
            const double expected = albedo * radiance * rectangle_form_factor(-0.5 * sx, 0.5 * sy, x0, x1, z0, z1, height);
            ratio[j * n + i] = out.film.mean.rgb[3 * (j * n + i)] / expected;
        }
    // Blocks of 8×8 pixels: each block's mean ratio is 1 within 5 standard
    // errors of that block (64 blocks).
    for (uint32_t bj = 0; bj < n; bj += 8)
        for (uint32_t bi = 0; bi < n; bi += 8) {
            double sum = 0.0, sum2 = 0.0;
            for (uint32_t j = bj; j < bj + 8; ++j)
                for (uint32_t i = bi; i < bi + 8; ++i) {
                    sum += ratio[j * n + i];
                    sum2 += ratio[j * n + i] * ratio[j * n + i];
                }
            const double mean = sum / 64.0;
            const double se = std::sqrt((sum2 / 64.0 - mean * mean) / 63.0);
            EXPECT_NEAR(mean, 1.0, 5.0 * se + 1e-3) << "block at pixel (" << bi << ", " << bj << ")";
        }
}

// Depth 1 is direct lighting alone; with unlimited depth nothing changes here,
// since the emitter reflects nothing back.
INSTANTIATE_TEST_SUITE_P(Depth, NextEventEstimation, ::testing::Values(1u, WF_UNLIMITED_DEPTH),
                         [](const ::testing::TestParamInfo<uint32_t>& info) {
                             return info.param == WF_UNLIMITED_DEPTH ? std::string("Unlimited")
                                                                     : "Max" + std::to_string(info.param);
                         });

} // namespace
} // namespace wf
