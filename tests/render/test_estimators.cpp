// test_estimators.cpp — the sampling techniques are all unbiased, converge at
// the rate Monte Carlo promises, and the render's own error estimate can be
// trusted.
//
// Unbiasedness follows Mitsuba 3's render tests: every technique's image is
// compared with a high-sample reference by a Z-test on blocks of pixels, using
// both images' own variance, with a Bonferroni correction for the number of
// comparisons. Each render has a fixed seed, so an outcome never changes.
//
// Blocks are 8x8 pixels, not single pixels: BRDF sampling alone finds the
// light from grazing surfaces near the image's top edge so rarely that at 256
// spp many pixels there have seen no light and report zero variance, and a
// per-pixel (or 4x4) test fails on that missing variance, not on bias. Over 8x8
// blocks (16384 samples) the largest |z| measured across all 12 techniques was
// 2.9 in 576 comparisons.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "image/error_metrics.h"
#include "gltf/gltf_loader.h"
#include "render/renderer.h"
#include "support/statistics.h"
#include "support/test_support.h"

namespace wf {
namespace {

constexpr uint32_t kSide = 32;
constexpr uint32_t kReferenceSpp = 2048;

const Scene& cornell() {
    static const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    return scene;
}

FilmReadout render_cornell(RenderSettings settings) {
    Renderer renderer(test::cpu_device(), cornell(), *cornell().camera, ImageSize{kSide, kSide}, settings);
    renderer.render_to(settings.spp);
    return renderer.read();
}

// The best technique at many samples, rendered once for every test here.
const FilmReadout& cornell_reference() {
    static const FilmReadout reference = [] {
        RenderSettings s;
        s.spp = kReferenceSpp;
        s.seed = 1000;
        return render_cornell(s);
    }();
    return reference;
}

constexpr uint32_t kBlock = 8;

struct Technique {
    uint32_t light_sampling, hemisphere, sampler;
};

std::vector<Technique> every_technique() {
    std::vector<Technique> all;
    for (uint32_t l : {WF_LIGHT_SAMPLING_BSDF, WF_LIGHT_SAMPLING_NEE, WF_LIGHT_SAMPLING_MIS})
        for (uint32_t h : {WF_HEMISPHERE_UNIFORM, WF_HEMISPHERE_COSINE})
            for (uint32_t s : {WF_SAMPLER_INDEPENDENT, WF_SAMPLER_SOBOL}) all.push_back({l, h, s});
    return all;
}

TEST(Unbiasedness, EveryTechniqueConvergesToTheReference) {
    const std::vector<Technique> techniques = every_technique();
    const size_t comparisons = techniques.size() * (kSide / kBlock) * (kSide / kBlock) * 3;
    // A family-wise false-alarm rate of 1% over 576 comparisons: |z| < 4.4.
    const double threshold = test::bonferroni_threshold(0.01, comparisons);
    for (const Technique& t : techniques) {
        RenderSettings s;
        s.spp = 256;
        s.seed = 7;
        s.light_sampling = t.light_sampling;
        s.hemisphere = t.hemisphere;
        s.sampler = t.sampler;
        const double z = test::max_block_z(render_cornell(s), cornell_reference(), kBlock);
        EXPECT_LT(z, threshold) << "light sampling " << t.light_sampling << ", hemisphere " << t.hemisphere
                                << ", sampler " << t.sampler;
    }
}

// Least-squares slope of log(y) against log(x).
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = x.size();
    for (size_t i = 0; i < x.size(); ++i) {
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Two renders with different seeds are independent and unbiased (above), so
// half the mean squared difference of their pixels is the MSE of either. At
// 32x32 a handful of pixels on the light's edge (values 0.3 or 47) dominate
// the MSE, so one pair's slope wanders by ±0.1 (measured: −1.05, −0.91, −0.96
// over 4–1024 spp); the mean over three pairs is the estimate tested.
TEST(Convergence, IndependentSamplingMseFallsAsOneOverSpp) {
    std::vector<double> spp = {4, 16, 64, 256, 1024}, mse(spp.size(), 0.0);
    for (uint32_t pair = 0; pair < 3; ++pair) {
        RenderSettings a, b;
        a.seed = 100 + 2 * pair;
        b.seed = 101 + 2 * pair;
        a.sampler = b.sampler = WF_SAMPLER_INDEPENDENT;
        Renderer ra(test::cpu_device(), cornell(), *cornell().camera, ImageSize{kSide, kSide}, a);
        Renderer rb(test::cpu_device(), cornell(), *cornell().camera, ImageSize{kSide, kSide}, b);
        for (size_t i = 0; i < spp.size(); ++i) {
            ra.render_to(static_cast<uint32_t>(spp[i]));
            rb.render_to(static_cast<uint32_t>(spp[i]));
            mse[i] += compare_images(ra.read().mean, rb.read().mean).mse / 6.0;
        }
    }
    EXPECT_NEAR(log_log_slope(spp, mse), -1.0, 0.15);
}

// The floor under a rectangular light, direct lighting only: the light's
// 2D point and the pixel's footprint are both smooth integrands, where a
// stratified sequence beats independent samples at equal spp.
TEST(Convergence, SobolBeatsIndependentOnDirectLighting) {
    Scene scene;
    const uint32_t floor = test::add_material(scene, glm::vec3(0.5f), glm::vec3(0.0f), false);
    const uint32_t light = test::add_material(scene, glm::vec3(0.0f), glm::vec3(10.0f), false);
    test::add_quad(scene, {-50, 0, 50}, {50, 0, 50}, {50, 0, -50}, {-50, 0, -50}, floor);
    test::add_quad(scene, {-0.5f, 1, -0.25f}, {0.5f, 1, -0.25f}, {0.5f, 1, 0.75f}, {-0.5f, 1, 0.75f}, light);
    SceneCamera camera;
    camera.position = {0, 0.5f, 0};
    camera.forward = {0, -1, 0};
    camera.up = {0, 0, 1};
    camera.vertical_fov = 1.5f;
    auto render = [&](uint32_t spp, uint32_t sampler, uint32_t seed) {
        RenderSettings s;
        s.spp = spp;
        s.max_depth = 1;
        s.sampler = sampler;
        s.seed = seed;
        Renderer r(test::cpu_device(), scene, camera, ImageSize{kSide, kSide}, s);
        r.render_to(spp);
        return r.read().mean;
    };
    const Image reference = render(8192, WF_SAMPLER_SOBOL, 99);
    const double independent = compare_images(render(16, WF_SAMPLER_INDEPENDENT, 5), reference).mse;
    const double sobol = compare_images(render(16, WF_SAMPLER_SOBOL, 5), reference).mse;
    EXPECT_LT(sobol, 0.5 * independent) << "sobol " << sobol << ", independent " << independent;
}

// The relMSE estimated from the render's own variance, against the relMSE
// measured against a reference, on two scenes: with independent samples
// within a factor of 1.5 from 64 spp on. Sobol points are stratified, which
// s^2/n does not know, so for them the estimate is pessimistic (measured
// 1.7-2.2x): above the true error, never below it, which is the side
// --target-error needs.
TEST(ErrorEstimate, TracksTheTrueError) {
    struct Bounds {
        uint32_t sampler;
        double low, high;
        const char* name;
    };
    const Scene furnace = test::furnace_box(0.7f, 1.0f);
    SceneCamera inside;
    inside.position = {0.2f, 0.1f, -0.3f};
    const Image exact_furnace{kSide, kSide, std::vector<float>(3 * kSide * kSide, float(1.0 / (1.0 - 0.7)))};
    for (const Bounds& b : {Bounds{WF_SAMPLER_INDEPENDENT, 1.0 / 1.5, 1.5, "independent"},
                            Bounds{WF_SAMPLER_SOBOL, 1.0, 3.0, "sobol"}})
        for (uint32_t spp : {64u, 256u}) {
            const auto expect_tracks = [&](const FilmReadout& image, const Image& truth, const std::string& scene) {
                const double ratio = estimate_relmse(image.mean, image.variance_of_mean) /
                                     compare_images(image.mean, truth).relmse;
                const std::string what = scene + ", " + b.name + ", " + std::to_string(spp) + " spp";
                test::report_measured("error estimate / true, " + what + ": " + std::to_string(ratio));
                EXPECT_GT(ratio, b.low) << what;
                EXPECT_LT(ratio, b.high) << what;
            };
            RenderSettings s;
            s.spp = spp;
            s.seed = 3;
            s.sampler = b.sampler;
            expect_tracks(render_cornell(s), cornell_reference().mean, "Cornell box");
            // The furnace: every pixel's true value is known exactly.
            Renderer r(test::cpu_device(), furnace, inside, ImageSize{kSide, kSide}, s);
            r.render_to(spp);
            expect_tracks(r.read(), exact_furnace, "furnace");
        }
}

} // namespace
} // namespace wf
