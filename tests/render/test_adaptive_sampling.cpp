// test_adaptive_sampling.cpp — --adaptive: which pixels go on (the 3×3 mean
// of their estimated error against the target, widened by a neighbour), and
// that a pixel which stopped at N samples has exactly the bytes a uniform
// render of N gives it, on every schedule and both integrators, so that the
// same flags and seed give the same image.
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

// A grey image whose variance is zero but at the pixels `errors` names,
// where it gives that estimated relMSE.
struct ErrorImage {
    Image mean, variance;
    ErrorImage(uint32_t width, uint32_t height, const std::vector<std::pair<uint32_t, double>>& errors) {
        mean = Image{width, height, std::vector<float>(3 * size_t{width} * height, 0.5f), {}};
        variance = Image{width, height, std::vector<float>(3 * size_t{width} * height, 0.0f), {}};
        for (const auto& [pixel, error] : errors)
            for (int k = 0; k < 3; ++k) variance.rgb[3 * pixel + k] = static_cast<float>(error * (0.25 + 0.01));
    }
};

TEST(AdaptiveSampling, APixelAboveTheTargetKeepsItsNeighbourhoodGoingOn) {
    // 9× the target at (5, 4) of a 10×8 image: every 3×3 mean that holds it
    // is the target (it is one of nine), so pixels up to two steps away go on.
    const uint32_t hot = 4 * 10 + 5;
    const double target = 1e-3;
    const ErrorImage image(10, 8, {{hot, 9.0 * target * 1.0001}});
    const std::vector<uint32_t> going_on = unfinished_pixels(image.mean, image.variance, target, every_pixel(10, 8));
    std::vector<uint32_t> expected;
    for (uint32_t y = 2; y <= 6; ++y)
        for (uint32_t x = 3; x <= 7; ++x) expected.push_back(y * 10 + x);
    EXPECT_EQ(going_on, expected);
    EXPECT_NEAR(estimate_pixel_relmse(image.mean, image.variance, hot), 9.0 * target * 1.0001, 1e-9);
}

TEST(AdaptiveSampling, ALoneOutlierIsAveragedAwayAndStoppedPixelsStayStopped) {
    const double target = 1e-3;
    // 8× the target alone: its 3×3 means are below the target (one of nine).
    const ErrorImage lone(10, 8, {{4 * 10 + 5, 8.0 * target}});
    EXPECT_TRUE(unfinished_pixels(lone.mean, lone.variance, target, every_pixel(10, 8)).empty());
    // In a corner the window holds four pixels: 4× the target there meets it
    // in the corner's window alone, which keeps the corner and its neighbours
    // going on.
    const ErrorImage corner(10, 8, {{0, 4.0 * target}});
    EXPECT_EQ(unfinished_pixels(corner.mean, corner.variance, target, every_pixel(10, 8)),
              (std::vector<uint32_t>{0, 1, 10, 11}));
    // Of those, only the ones still going on.
    EXPECT_EQ(unfinished_pixels(corner.mean, corner.variance, target, {1, 11, 30}), (std::vector<uint32_t>{1, 11}));
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

// The target half the pixels of `uniform16` meet.
double median_error(const FilmState& uniform16) {
    const FilmReadout film = resolve(uniform16);
    std::vector<double> errors;
    for (size_t p = 0; p < size_t{kSize.width} * kSize.height; ++p)
        errors.push_back(estimate_pixel_relmse(film.mean, film.variance_of_mean, p));
    std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
    return errors[errors.size() / 2];
}

bool same_pixel(const FilmState& a, const FilmState& b, size_t p) {
    return a.samples[p] == b.samples[p] && std::memcmp(&a.sum[p], &b.sum[p], sizeof(cl_float4)) == 0 &&
           std::memcmp(&a.compensation[p], &b.compensation[p], sizeof(cl_float4)) == 0 &&
           std::memcmp(&a.sum_squares[p], &b.sum_squares[p], sizeof(cl_float4)) == 0;
}

// The samples each pixel should end with, from uniform renders alone: after
// each round the film is, pixel by pixel, the uniform render of the count the
// pixel has, and the rule picks which pixels go on from it.
std::vector<uint32_t> expected_counts(std::map<uint32_t, FilmState>& uniform, double target) {
    FilmState film = uniform[16];
    std::vector<uint32_t> going_on = every_pixel(kSize.width, kSize.height);
    for (const uint32_t spp : {16u, 32u, 64u}) {
        for (const uint32_t p : going_on) {
#define WF_COPY_PIXEL(type, name, extent, what)                                                                        \
    if (std::string(#extent) == "PIXEL") film.name[p] = uniform[spp].name[p];
            WF_FILM_BUFFERS(WF_COPY_PIXEL)
#undef WF_COPY_PIXEL
        }
        const FilmReadout readout = resolve(film);
        going_on = unfinished_pixels(readout.mean, readout.variance_of_mean, target, going_on);
    }
    return film.samples;
}

TEST(AdaptiveSampling, APixelStoppedAtNSamplesHasTheBytesOfAUniformRenderOfN) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    std::map<uint32_t, FilmState> uniform;
    for (const uint32_t spp : {16u, 32u, 64u}) uniform[spp] = render_uniform(scene, RenderSettings{}, spp);
    const double target = median_error(uniform[16]);
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

TEST(AdaptiveSampling, EveryPixelUnderTheTargetEndsTheRender) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    RenderSettings settings;
    settings.aovs = WF_AOV_SAMPLES;
    Renderer renderer(test::cpu_device(), scene, *scene.camera, kSize, settings);
    ProgressOptions options;
    options.target_relmse = 0.05;
    options.adaptive = true;
    std::vector<Checkpoint> checkpoints;
    const FilmReadout film =
        render_progressively(renderer, 0, options, [&](const Checkpoint& c) { checkpoints.push_back(c); });
    ASSERT_FALSE(checkpoints.empty());
    EXPECT_EQ(checkpoints.back().pixels_sampling, 0u);
    ASSERT_TRUE(film.samples);
    const auto [fewest, most] = std::minmax_element(film.samples->rgb.begin(), film.samples->rgb.end());
    EXPECT_EQ(*fewest, 16.0f);
    EXPECT_GT(*most, 16.0f);
    const std::vector<uint32_t> still = unfinished_pixels(film.mean, film.variance_of_mean, options.target_relmse,
                                                          every_pixel(kSize.width, kSize.height));
    // Each pixel stopped under the target at its own last round: none of the
    // most-sampled is still above it now.
    for (const uint32_t p : still) EXPECT_LT(film.samples->rgb[3 * p], *most) << p;
}

} // namespace
} // namespace wf
