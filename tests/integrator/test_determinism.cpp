// test_determinism.cpp — the image depends on the scene, the settings and the
// seed, never on how the work was scheduled: pool sizes (dividing the pixel
// count or not), local sizes, the wavefront's schedules and the megakernel
// give the same bytes.
#include <cstring>
#include <stdexcept>

#include <gtest/gtest.h>

#include "gltf/gltf_loader.h"
#include "integrator/path_integrator.h"
#include "render/renderer.h"
#include "support/test_support.h"

namespace wf {
namespace {

RenderOutput render_file(const std::string& path, RenderSettings settings, ImageSize size = {40, 30}) {
    const Scene scene = load_gltf(path);
    settings.spp = 4;
    return render_scene(test::cpu_device(), scene, *scene.camera, size, settings);
}

Image render_cornell(uint32_t pool_size, uint32_t local_size, uint32_t seed, Schedule schedule = Schedule::Refill) {
    RenderSettings settings;
    settings.schedule = schedule;
    settings.seed = seed;
    settings.pool_size = pool_size;
    settings.local_size = local_size;
    return render_file(WF_SOURCE_DIR "/scenes/cornell-box.gltf", settings).film.mean;
}

bool same_bytes(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

TEST(Determinism, PoolAndLocalSizeDoNotChangeOneBit) {
    const Image reference = render_cornell(1200, 64, 3); // one slot per pixel
    EXPECT_TRUE(same_bytes(reference, render_cornell(256, 64, 3)));
    EXPECT_TRUE(same_bytes(reference, render_cornell(777, 64, 3))); // does not divide 1200
    EXPECT_TRUE(same_bytes(reference, render_cornell(1200, 32, 3)));
    EXPECT_FALSE(same_bytes(reference, render_cornell(1200, 64, 4))); // the seed does matter
    // The group schedule, whose work-groups are its queues (and the default on a CPU).
    EXPECT_TRUE(same_bytes(reference, render_cornell(777, 64, 3, Schedule::Group)));
    EXPECT_TRUE(same_bytes(reference, render_cornell(256, 32, 3, Schedule::Group)));
}

// Stopping to look at the film between rounds changes nothing: a pixel's
// samples are still traced and summed in order by its owning slot.
TEST(Determinism, RoundsDoNotChangeOneBit) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    RenderSettings settings;
    settings.seed = 3;
    settings.pool_size = 777;
    Renderer progressive(test::cpu_device(), scene, *scene.camera, ImageSize{40, 30}, settings);
    for (uint32_t spp : {1u, 2u, 3u, 4u}) progressive.render_to(spp);
    EXPECT_TRUE(same_bytes(render_cornell(1200, 64, 3), progressive.read().mean));
}

// Every schedule, queue-push strategy and the megakernel run the same stage
// functions in the same order along each path, a BSDF kind's lanes give its
// width-1 bits, and a pixel's samples are still added in order by its one
// slot: the bytes are the same, on a scene that uses every kind of work
// (glossy and glass bounces, shadow rays, roulette; the layered kind's
// lobes, with and without a clear coat or sheen) and with a pool smaller
// than the image, so slots own several pixels.
struct DeterminismScene {
    const char* file;
    bool layered; // every opaque material under a rough coat, a smooth coat and a sheen, or a sheen, in turn
};

class ScheduleDeterminism : public ::testing::TestWithParam<DeterminismScene> {};

TEST_P(ScheduleDeterminism, EveryScheduleAndTheMegakernelGiveTheSameBytes) {
    Scene scene = load_gltf(std::string(WF_SOURCE_DIR "/scenes/") + GetParam().file);
    if (GetParam().layered)
        for (size_t i = 0; i < scene.materials.size(); ++i) {
            SceneMaterial& m = scene.materials[i];
            if (m.transmission > 0.0f) continue;
            m.clearcoat = i % 3 == 0 ? 1.0f : i % 3 == 1 ? 0.5f : 0.0f;
            m.clearcoat_roughness = i % 3 == 0 ? 0.3f : 0.0f;
            if (i % 3 != 0) m.sheen_color = glm::vec3(0.8f, 0.2f, 0.1f), m.sheen_roughness = 0.4f;
        }
    auto render = [&](RenderSettings s) {
        s.spp = 4;
        return render_scene(test::cpu_device(), scene, *scene.camera, ImageSize{40, 30}, s);
    };
    RenderSettings settings;
    settings.seed = 5;
    settings.pool_size = 500;
    settings.schedule = Schedule::Refill;
    const RenderOutput reference = render(settings);
    EXPECT_GT(reference.summary.stats.shadow_rays, 0u);
    for (const Schedule schedule : {Schedule::Passes, Schedule::Fullest, Schedule::Group}) {
        settings.schedule = schedule;
        const RenderOutput r = render(settings);
        EXPECT_TRUE(same_bytes(reference.film.mean, r.film.mean)) << schedule_name(schedule);
        EXPECT_EQ(r.summary.stats.closest_rays, reference.summary.stats.closest_rays) << schedule_name(schedule);
        EXPECT_EQ(r.summary.stats.shadow_rays, reference.summary.stats.shadow_rays) << schedule_name(schedule);
        EXPECT_EQ(r.summary.stats.path_lengths, reference.summary.stats.path_lengths) << schedule_name(schedule);
    }
    settings.schedule = Schedule::Group; // its work-groups are its queues: another local size, the same bytes
    settings.local_size = 128;
    EXPECT_TRUE(same_bytes(reference.film.mean, render(settings).film.mean)) << "group, local size 128";
    settings.local_size = RenderSettings{}.local_size;
    for (const uint32_t width : {1u, 8u, 16u}) { // its BSDF lanes (kernels/stages/shade_lanes.h), none to sixteen
        settings.lane_width = width;
        EXPECT_TRUE(same_bytes(reference.film.mean, render(settings).film.mean))
            << "group, lane width " << width;
    }
    settings.lane_width = RenderSettings{}.lane_width;
    // The lanes draw both samplers' numbers themselves, the Sobol sampler's
    // (the default) and the independent sampler's (kernels/stages/shade_lanes.h,
    // generate_lanes.h): either way, the bytes of a path at a time.
    settings.sampler = WF_SAMPLER_INDEPENDENT;
    const RenderOutput independent = render(settings);
    settings.schedule = Schedule::Refill;
    EXPECT_TRUE(same_bytes(render(settings).film.mean, independent.film.mean))
        << "group, independent sampler";
    settings.sampler = RenderSettings{}.sampler;
    // `changed` on each of `schedules`: the reference's bytes and shadow rays.
    auto expect_reference = [&](RenderSettings changed, std::initializer_list<Schedule> schedules,
                                const std::string& what) {
        for (const Schedule schedule : schedules) {
            changed.schedule = schedule;
            const RenderOutput r = render(changed);
            EXPECT_TRUE(same_bytes(reference.film.mean, r.film.mean)) << what << ", " << schedule_name(schedule);
            EXPECT_EQ(r.summary.stats.shadow_rays, reference.summary.stats.shadow_rays) << what;
        }
    };
    RenderSettings wide = settings;
    wide.trace_width = 2; // two rays a work-item (kernels/geometry/trace_width.h); these scenes' default is 1
    expect_reference(wide, {Schedule::Refill, Schedule::Group}, "trace width 2");
    RenderSettings split = settings;
    split.shade_kernels = 2; // shade as two kernels with a record between them (include/wavefront/shade_record.h)
    expect_reference(split, {Schedule::Refill, Schedule::Fullest}, "two shade kernels");
    RenderSettings gpu_push = settings;
    gpu_push.queue_push = QueuePush::Group; // a GPU's pushes (local atomics), where a CPU's default is serial
    expect_reference(gpu_push, {Schedule::Group}, "group push");
    settings.schedule = Schedule::Refill;
    for (const QueuePush push : {QueuePush::Group, QueuePush::Atomic, QueuePush::Scan, QueuePush::Serial}) {
        settings.queue_push = push;
        const RenderOutput r = render(settings);
        EXPECT_TRUE(same_bytes(reference.film.mean, r.film.mean)) << queue_push_name(push);
        EXPECT_EQ(r.summary.stats.closest_rays, reference.summary.stats.closest_rays) << queue_push_name(push);
    }
    settings.queue_push = RenderSettings{}.queue_push;
    settings.integrator = Integrator::Megakernel;
    const RenderOutput mega = render(settings);
    EXPECT_TRUE(same_bytes(reference.film.mean, mega.film.mean));
    EXPECT_EQ(mega.summary.stats.samples, reference.summary.stats.samples);
    EXPECT_EQ(mega.summary.stats.closest_rays, reference.summary.stats.closest_rays);
    EXPECT_EQ(mega.summary.stats.shadow_rays, reference.summary.stats.shadow_rays);
    EXPECT_EQ(mega.summary.stats.path_lengths, reference.summary.stats.path_lengths);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ScheduleDeterminism,
                         ::testing::Values(DeterminismScene{"cornell-box.gltf", false},
                                           DeterminismScene{"cornell-teapot.gltf", false},
                                           DeterminismScene{"cornell-glass.gltf", false},
                                           DeterminismScene{"cornell-glass.gltf", true}),
                         [](const ::testing::TestParamInfo<DeterminismScene>& info) {
                             std::string name = info.param.file;
                             name = name.substr(0, name.find('.'));
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return info.param.layered ? name + "_layered" : name;
                         });

// With no schedule asked for, the renderer picks the device's: group on a
// CPU (its stages keep a work-group's paths in one core's caches), refill on
// a GPU and wherever the material sort needs the global queue.
TEST(Schedules, TheDefaultIsGroupOnACpuAndRefillElsewhere) {
    EXPECT_EQ(default_schedule("cpu", false), Schedule::Group);
    EXPECT_EQ(default_schedule("cpu", true), Schedule::Refill);
    EXPECT_EQ(default_schedule("gpu", false), Schedule::Refill);
    RenderSettings settings;
    ASSERT_EQ(settings.schedule, Schedule::Auto);
    EXPECT_EQ(render_file(WF_SOURCE_DIR "/scenes/cornell-box.gltf", settings).summary.stats.schedule, Schedule::Group);
    settings.sort_materials = true;
    EXPECT_EQ(render_file(WF_SOURCE_DIR "/scenes/cornell-box.gltf", settings).summary.stats.schedule, Schedule::Refill);
}

// Shade runs as two kernels (include/wavefront/shade_record.h) where asked,
// and by default where a GPU's program runs a global-queue schedule; never in
// the megakernel or the group schedule, which keep a path in one kernel. The
// rule needs the schedule and the kind of kernels resolved.
TEST(Schedules, ShadeRunsAsTwoKernelsWhereAGpusProgramRunsAGlobalQueue) {
    RenderSettings s;
    EXPECT_THROW(shade_in_two_kernels(s), std::logic_error);
    s.kernels = KernelKind::Gpu;
    for (const Schedule schedule : {Schedule::Refill, Schedule::Passes, Schedule::Fullest}) {
        s.schedule = schedule;
        EXPECT_TRUE(shade_in_two_kernels(s)) << schedule_name(schedule);
    }
    s.shade_kernels = 1;
    EXPECT_FALSE(shade_in_two_kernels(s));
    s.shade_kernels = 0;
    s.kernels = KernelKind::Cpu;
    EXPECT_FALSE(shade_in_two_kernels(s));
    s.shade_kernels = 2;
    EXPECT_TRUE(shade_in_two_kernels(s));
    s.schedule = Schedule::Group;
    EXPECT_FALSE(shade_in_two_kernels(s));
    s.schedule = Schedule::Refill;
    s.integrator = Integrator::Megakernel;
    EXPECT_FALSE(shade_in_two_kernels(s));
}

// The passes schedule starts no sample while a path of the pass is in
// flight: whenever generate refills slots, no path was left to extend.
TEST(Schedules, PassesStartNewSamplesOnlyOnceThePoolIsEmpty) {
    RenderSettings settings;
    settings.schedule = Schedule::Passes;
    settings.pool_size = 300;
    const RenderOutput r = render_file(WF_SOURCE_DIR "/scenes/cornell-box.gltf", settings);
    const std::vector<CounterSnapshot>& reads = r.summary.stats.counter_reads;
    ASSERT_GT(reads.size(), 8u);
    uint32_t passes = 0;
    for (size_t i = 1; i < reads.size(); ++i) {
        // A read with rays traced beyond what the previous read left to extend started new samples.
        const bool started = reads[i].closest_rays > reads[i - 1].queues[WF_QUEUE_EXTEND];
        if (started) {
            ++passes;
            EXPECT_EQ(reads[i - 1].queues[WF_QUEUE_EXTEND], 0u) << "read " << i;
        }
    }
    // 1200 pixels, 300 slots, 4 spp: 16 passes, the first at the start of the round.
    EXPECT_EQ(passes + 1, 16u);
}

} // namespace
} // namespace wf
