// test_multi_device.cpp — a render shared by several devices gives the bytes
// of one device's: units of work cover each round's pixels once and in order,
// each pixel's sums follow it from device to device, and a render stopped
// anywhere goes on, with any devices and any pool, to the uninterrupted bytes.
// Two contexts on PoCL's one CPU device stand for two devices here (each has
// its own queue, pool and film); tests/cli/test_multi_device_cli.cpp runs two
// real PoCL devices.
#include <atomic>
#include <cstring>

#include <gtest/gtest.h>

#include "gltf/gltf_loader.h"
#include "render/renderer.h"
#include "render/work_units.h"
#include "support/test_support.h"

namespace wf {
namespace {

const std::string kScenes = WF_SOURCE_DIR "/scenes/";
constexpr ImageSize kSize{48, 36};

bool same_bytes(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

// A second context and queue on the test device: another device to a Renderer.
const OpenClDevice& second_device() {
    static const OpenClDevice device = open_device("cpu");
    return device;
}

std::vector<const OpenClDevice*> two_devices() { return {&test::cpu_device(), &second_device()}; }

TEST(WorkUnits, RunsCoverTheRoundInOrderAndShrinkTowardItsEnd) {
    WorkUnits units(100000, 2, 1000);
    std::vector<PixelRun> runs;
    for (PixelRun run; (run = units.next(30000)).count > 0;) runs.push_back(run);
    uint32_t next = 0;
    for (size_t i = 0; i < runs.size(); ++i) {
        EXPECT_EQ(runs[i].first, next);
        EXPECT_LE(runs[i].count, i ? runs[i - 1].count : 30000u);
        next += runs[i].count;
        if (i + 1 < runs.size()) EXPECT_GE(runs[i].count, 1000u) << i; // the last may be less
    }
    EXPECT_EQ(next, 100000u);
    ASSERT_GT(runs.size(), 8u);
    EXPECT_EQ(runs[runs.size() - 2].count, 1000u); // the runs shrank to the least
    EXPECT_EQ(units.next(30000).count, 0u);          // and the round stays handed out
}

struct Case {
    const char* scene;
    Integrator integrator;
    Schedule schedule;
};

class MultiDevice : public ::testing::TestWithParam<Case> {};

// Rounds of 1, 3 and 6 spp: each round cuts the image differently, so units
// meet pixels whose sums another device left.
TEST_P(MultiDevice, TwoDevicesGiveTheBytesOfOne) {
    const Scene scene = load_gltf(kScenes + GetParam().scene);
    RenderSettings settings;
    settings.seed = 7;
    settings.integrator = GetParam().integrator;
    settings.schedule = GetParam().schedule;
    settings.bounce_layers = 3;
    settings.pool_size = 300; // units of at most 300 pixels: many of them, on both devices
    Renderer one(test::cpu_device(), scene, *scene.camera, kSize, settings);
    Renderer two(two_devices(), scene, *scene.camera, kSize, settings);
    for (uint32_t spp : {1u, 3u, 6u}) {
        one.render_to(spp);
        two.render_to(spp);
    }
    const FilmReadout a = one.read(), b = two.read();
    EXPECT_TRUE(same_bytes(a.mean, b.mean));
    ASSERT_EQ(b.bounce_layers.size(), 3u);
    for (size_t l = 0; l < 3; ++l) EXPECT_TRUE(same_bytes(a.bounce_layers[l], b.bounce_layers[l])) << "layer " << l;
    EXPECT_EQ(b.min_samples, 6u);

    const RenderSummary s = two.summary();
    EXPECT_EQ(s.stats.samples, one.stats().samples);
    EXPECT_EQ(s.stats.closest_rays, one.stats().closest_rays);
    ASSERT_EQ(s.shares.size(), 2u);
    EXPECT_EQ(s.shares[0].samples + s.shares[1].samples, s.stats.samples);
    EXPECT_GE(s.shares[0].units + s.shares[1].units, 3u * (kSize.width * kSize.height / 300));
}

INSTANTIATE_TEST_SUITE_P(, MultiDevice,
                         ::testing::Values(Case{"cornell-box.gltf", Integrator::Wavefront, Schedule::Group},
                                           Case{"cornell-box.gltf", Integrator::Wavefront, Schedule::Refill},
                                           Case{"cornell-box.gltf", Integrator::Megakernel, Schedule::Auto},
                                           Case{"cornell-glass.gltf", Integrator::Wavefront, Schedule::Fullest}),
                         [](const auto& info) {
                             std::string name = info.param.scene;
                             name = name.substr(0, name.find('.'));
                             for (char& c : name) c = c == '-' ? '_' : c;
                             return name + "_" + integrator_name(info.param.integrator) + "_" +
                                    (info.param.integrator == Integrator::Megakernel
                                         ? std::string("whole")
                                         : schedule_name(info.param.schedule));
                         });

// Stopped after a few reads of the counters, two devices leave pixels of a
// round at different counts, which no pool's order leaves; one device with
// another pool goes on from there by units, to the bytes of a render never stopped.
TEST(MultiDeviceResume, AStoppedRenderGoesOnWithAnyDevicesAndPool) {
    const Scene scene = load_gltf(kScenes + "cornell-box.gltf");
    RenderSettings settings;
    settings.seed = 9;
    settings.pool_size = 250;
    std::atomic<int> stop{0};
    settings.stop = &stop;
    Renderer stopped(two_devices(), scene, *scene.camera, kSize, settings);
    int reads = 0;
    stopped.on_progress([&](const RenderStats&) {
        if (++reads == 6) stop = 1;
    });
    stopped.render_to(8);
    const FilmState partial = stopped.film_state();
    const auto [least, most] = std::minmax_element(partial.samples.begin(), partial.samples.end());
    ASSERT_LT(*least, 8u) << "the stop came after the round";
    ASSERT_GT(*most, *least) << "the stop left every pixel alike";

    settings.stop = nullptr;
    settings.pool_size = 333;
    Renderer resumed(test::cpu_device(), scene, *scene.camera, kSize, settings);
    EXPECT_EQ(resumed.resume(partial), *least);
    resumed.render_to(8);
    Renderer direct(test::cpu_device(), scene, *scene.camera, kSize, settings);
    direct.render_to(8);
    EXPECT_TRUE(same_bytes(resumed.read().mean, direct.read().mean));
    EXPECT_EQ(resumed.read().min_samples, 8u);

    Renderer resumed_on_two(two_devices(), scene, *scene.camera, kSize, settings);
    resumed_on_two.resume(partial);
    resumed_on_two.render_to(8);
    EXPECT_TRUE(same_bytes(resumed_on_two.read().mean, direct.read().mean));
}

} // namespace
} // namespace wf
