// test_adaptive_sampling.cpp — --adaptive: which pixels go on (as many
// samples as the square root of their variance is worth, toward the target),
// that a pixel which stopped at N samples has exactly the bytes a uniform
// render of N gives it, on every schedule and both integrators, so that the
// same flags and seed give the same image, and that the render ends on the
// image's error.
#include <algorithm>
#include <cstring>
#include <map>

#include <gtest/gtest.h>

#include "gltf/gltf_loader.h"
#include "image/error_metrics.h"
#include "render/adaptive_sampling.h"
#include "render/progressive_render.h"
#include "render/renderer.h"
#include "support/test_support.h"

namespace wf {
namespace {

// A grey film whose pixels have the estimated relMSE `error(x, y)`.
template <class Error> FilmReadout film_with_errors(uint32_t width, uint32_t height, Error error) {
    FilmReadout film;
    film.mean = Image{width, height, std::vector<float>(3 * size_t{width} * height, 0.5f), {}};
    film.variance_of_mean = film.mean;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            for (int k = 0; k < 3; ++k)
                film.variance_of_mean.rgb[3 * (size_t{y} * width + x) + k] =
                    static_cast<float>(error(x, y) * (0.25 + 0.01)); // relMSE = variance / (0.5² + 0.01)
    return film;
}

TEST(AdaptiveSampling, WhereTheVarianceIsEvenEveryPixelGoesOnUntilTheTarget) {
    const FilmReadout film = film_with_errors(12, 10, [](uint32_t, uint32_t) { return 1e-2; });
    EXPECT_NEAR(estimate_pixel_relmse(film.mean, film.variance_of_mean, 7), 1e-2, 1e-8);
    AdaptiveSampling above(12, 10, 0.9e-2);
    above.update(film, 16);
    EXPECT_EQ(above.going_on().size(), 120u); // uniform sampling is the best there is
    AdaptiveSampling below(12, 10, 1.1e-2);
    below.update(film, 16);
    EXPECT_TRUE(below.going_on().empty());
}

// The right half's per-sample variance 16x the left's: the best allocation
// gives it 4x the samples. A target for which the left half's share is 12
// samples stops it at 16 and keeps the right half (48) going on; the column
// each side of the border, whose 3x3 means mix both, is not checked.
TEST(AdaptiveSampling, SamplesGoWhereTheVarianceIs) {
    const double left = 1e-3; // relMSE at 16 samples; the right half's is 16x
    const FilmReadout film = film_with_errors(12, 10, [&](uint32_t x, uint32_t) { return x < 6 ? left : 16 * left; });
    // v = 16·left on the left, 16x that on the right: mean √v = 2.5·√(16·left), n* = √v / √λ.
    const double v_left = 16 * left, target = 2.5 * v_left / 12.0;
    AdaptiveSampling adaptive(12, 10, target);
    adaptive.update(film, 16);
    const std::vector<uint32_t>& going_on = adaptive.going_on();
    for (uint32_t y = 0; y < 10; ++y)
        for (uint32_t x = 0; x < 12; ++x) {
            const bool goes_on = std::binary_search(going_on.begin(), going_on.end(), y * 12 + x);
            if (x < 5) EXPECT_FALSE(goes_on) << x << "," << y;
            if (x > 6) EXPECT_TRUE(goes_on) << x << "," << y;
        }
    // The next round: only pixels that went on can go on, with their new count.
    const std::vector<uint32_t> before = going_on;
    adaptive.update(film, 32);
    for (const uint32_t p : adaptive.going_on()) EXPECT_TRUE(std::binary_search(before.begin(), before.end(), p)) << p;
    EXPECT_EQ(adaptive.samples()[0], 16u);
    EXPECT_EQ(adaptive.samples()[11], 32u);
}

constexpr ImageSize kSize{32, 24};
constexpr uint32_t kMostSpp = 64;

FilmState render_uniform(const Scene& scene, RenderSettings settings, uint32_t spp) {
    Renderer renderer(test::cpu_device(), scene, *scene.camera, kSize, settings);
    renderer.render_to(spp);
    return renderer.film_state();
}

FilmState render_adaptive(const Scene& scene, const RenderSettings& settings, double target) {
    Renderer renderer(test::cpu_device(), scene, *scene.camera, kSize, settings);
    ProgressOptions options;
    options.target_relmse = target;
    options.adaptive = true;
    render_progressively(renderer, kMostSpp, options, [](const Checkpoint&) {});
    return renderer.film_state();
}

bool same_pixel(const FilmState& a, const FilmState& b, size_t p) {
    return a.samples[p] == b.samples[p] && std::memcmp(&a.sum[p], &b.sum[p], sizeof(cl_float4)) == 0 &&
           std::memcmp(&a.compensation[p], &b.compensation[p], sizeof(cl_float4)) == 0 &&
           std::memcmp(&a.sum_squares[p], &b.sum_squares[p], sizeof(cl_float4)) == 0;
}

// The samples each pixel should end with, from uniform renders alone: after
// each round the film is, pixel by pixel, the uniform render of the count the
// pixel has, and adaptive sampling picks which pixels go on from it.
std::vector<uint32_t> expected_counts(std::map<uint32_t, FilmState>& uniform, double target) {
    FilmState film = uniform[16];
    AdaptiveSampling adaptive(kSize.width, kSize.height, target);
    for (const uint32_t spp : {16u, 32u, 64u}) {
        for (const uint32_t p : adaptive.going_on()) {
#define WF_COPY_PIXEL(type, name, extent, what)                                                                        \
    if (std::string(#extent) == "PIXEL") film.name[p] = uniform[spp].name[p];
            WF_FILM_BUFFERS(WF_COPY_PIXEL)
#undef WF_COPY_PIXEL
        }
        adaptive.update(resolve(film), spp);
    }
    return film.samples;
}

TEST(AdaptiveSampling, APixelStoppedAtNSamplesHasTheBytesOfAUniformRenderOfN) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    std::map<uint32_t, FilmState> uniform;
    for (const uint32_t spp : {16u, 32u, 64u}) uniform[spp] = render_uniform(scene, RenderSettings{}, spp);
    // Below what uniform sampling reaches at 64 spp: the render goes on to the cap of 64.
    const double target = 0.8 * estimate_relmse(resolve(uniform[64]).mean, resolve(uniform[64]).variance_of_mean);
    const std::vector<uint32_t> expected = expected_counts(uniform, target);

    struct Variant {
        const char* name;
        Integrator integrator;
        Schedule schedule;
        uint32_t pool_size;
    };
    for (const Variant& v : {Variant{"group", Integrator::Wavefront, Schedule::Group, 0},
                             Variant{"refill, a pool of 100", Integrator::Wavefront, Schedule::Refill, 100},
                             Variant{"megakernel", Integrator::Megakernel, Schedule::Auto, 0}}) {
        SCOPED_TRACE(v.name);
        RenderSettings settings;
        settings.integrator = v.integrator;
        settings.schedule = v.schedule;
        settings.pool_size = v.pool_size;
        const FilmState adaptive = render_adaptive(scene, settings, target);
        EXPECT_EQ(adaptive.samples,
                  expected); // the rule's pixels went on, and they alone
        std::map<uint32_t, int> counts;
        size_t differ = 0;
        for (size_t p = 0; p < adaptive.samples.size(); ++p) {
            const uint32_t n = adaptive.samples[p];
            ++counts[n];
            if (!uniform.count(n) || !same_pixel(adaptive, uniform[n], p)) ++differ;
        }
        EXPECT_EQ(differ, 0u);
        // Pixels stopped after each of the three rounds.
        EXPECT_EQ(counts.size(), 3u);
        for (const auto& [n, pixels] : counts) EXPECT_GT(pixels, 10) << n << " samples";
        test::report_measured(std::string(v.name) + ": pixels at 16/32/64 spp " + std::to_string(counts[16]) + "/" +
                              std::to_string(counts[32]) + "/" + std::to_string(counts[64]));
    }
}

TEST(AdaptiveSampling, TheRenderEndsWhenTheImageMeetsTheTarget) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    RenderSettings settings;
    settings.aovs = WF_AOV_SAMPLES;
    Renderer renderer(test::cpu_device(), scene, *scene.camera, kSize, settings);
    ProgressOptions options;
    options.target_relmse = 0.01;
    options.adaptive = true;
    std::vector<Checkpoint> checkpoints;
    const FilmReadout film =
        render_progressively(renderer, 0, options, [&](const Checkpoint& c) { checkpoints.push_back(c); });
    ASSERT_GE(checkpoints.size(), 2u);
    EXPECT_LT(*checkpoints.back().relmse_estimate, options.target_relmse);
    EXPECT_GE(*checkpoints[checkpoints.size() - 2].relmse_estimate, options.target_relmse);
    EXPECT_LT(checkpoints.back().pixels_sampling, kSize.width * kSize.height);
    ASSERT_TRUE(film.samples);
    const auto [fewest, most] = std::minmax_element(film.samples->rgb.begin(), film.samples->rgb.end());
    EXPECT_EQ(*fewest, 16.0f);
    EXPECT_GT(*most, 16.0f);
}

} // namespace
} // namespace wf
