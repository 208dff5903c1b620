// render_settings.h — what a render is asked to do: samples, depth, seed,
// pool and work-group sizes, the sampling techniques, the integrator and its
// schedule; and the one table of names of each choice, which the command
// line parses, the report prints and the image metadata records. No OpenCL
// here: the command line fills these in without knowing a device.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "wavefront/aovs.h"
#include "wavefront/techniques.h"

namespace wf {

enum class Integrator { Wavefront, Megakernel };

// In which order the wavefront launches its stages (wavefront_integrator.cpp).
enum class Schedule {
    Refill,  // every stage once per iteration, freed slots refilled at once
    Passes,  // pbrt-v4: a pass of one sample per slot runs to its end before the next starts
    Fullest, // Cycles X: the stage whose queue the device counters show fullest, one at a time
    Group,   // every stage inside each work-group, over local queues: one launch a sample of each slot
    Auto,    // chosen by the renderer for the device: default_schedule() (path_integrator.h)
};

// How the kernels append to queues and counters (kernels/common/queue_push.h),
// in the order of its WF_PUSH_* values; Auto: the kind of kernels' own
// (queue_push_for, render/device_renderer.cpp).
enum class QueuePush { Group, Atomic, Scan, Serial, Auto };

// Which device kind's kernels to build (render_program_source, device_renderer.h):
// the device's own, or another kind's, so that a GPU's kernels run and are
// tested on a CPU device.
enum class KernelKind { Cpu, Gpu, Auto };

// Each choice's names, indexed by its enum or WF_* value.
using ChoiceNames = std::array<const char*, 5>; // unused entries are null
constexpr ChoiceNames kIntegratorNames = {"wavefront", "megakernel", nullptr};
constexpr ChoiceNames kScheduleNames = {"refill", "passes", "fullest", "group", "auto"};
constexpr ChoiceNames kQueuePushNames = {"group", "atomic", "scan", "serial", "auto"};
constexpr ChoiceNames kKernelKindNames = {"cpu", "gpu", "auto"};
constexpr ChoiceNames kLightSamplingNames = {"bsdf", "nee", "mis"};
constexpr ChoiceNames kHemisphereNames = {"uniform", "cosine", nullptr};
constexpr ChoiceNames kSamplerNames = {"independent", "sobol", nullptr};
// --aov's layers of one bit by name (the bounce layers are the other choice, "bounces").
constexpr std::array<std::pair<const char*, uint32_t>, 4> kAovBits = {
    {{"albedo", WF_AOV_ALBEDO}, {"normal", WF_AOV_NORMAL}, {"depth", WF_AOV_DEPTH}, {"samples", WF_AOV_SAMPLES}}};
static_assert(WF_LIGHT_SAMPLING_BSDF == 0 && WF_LIGHT_SAMPLING_NEE == 1 && WF_LIGHT_SAMPLING_MIS == 2);
static_assert(WF_HEMISPHERE_UNIFORM == 0 && WF_HEMISPHERE_COSINE == 1);
static_assert(WF_SAMPLER_INDEPENDENT == 0 && WF_SAMPLER_SOBOL == 1);

inline const char* choice_name(const ChoiceNames& names, uint32_t value) { return names.at(value); }
// The value named `name`, if one is.
inline std::optional<uint32_t> choice_value(const ChoiceNames& names, const std::string& name) {
    for (uint32_t i = 0; i < names.size(); ++i)
        if (names[i] && name == names[i]) return i;
    return std::nullopt;
}
inline const char* integrator_name(Integrator i) { return choice_name(kIntegratorNames, static_cast<uint32_t>(i)); }
inline const char* schedule_name(Schedule s) { return choice_name(kScheduleNames, static_cast<uint32_t>(s)); }
inline const char* kernel_kind_name(KernelKind k) { return choice_name(kKernelKindNames, static_cast<uint32_t>(k)); }
inline const char* queue_push_name(QueuePush p) { return choice_name(kQueuePushNames, static_cast<uint32_t>(p)); }

// Paths in flight when the command line names none (at most the pixel count).
// A GPU hides memory latency with many paths in flight: kGpuPathsPerComputeUnit
// a compute unit, four times the 2048 threads an NVIDIA multiprocessor holds
// at once, and at least kDefaultPoolSize. On an H200 (132 units) the
// wavefront ran the Cornell box 2048 wide at 189, 284 and 324 M samples/s
// with 2^18, 2^20 and 2^22 paths, the launches' host share 41%, 20% and 14%
// (bench/results/gpu-run.md). On a CPU the wavefront runs each stage over the
// whole pool, so a pool whose state stays in the caches is faster: 2^15 paths
// are 4 MiB of path state, and on the Cornell box, 512 wide, 64 spp, PoCL on
// 2 cores, the wavefront ran 1.5-1.7x faster than with 2^18. The megakernel
// takes each path through every stage at once and ran 5-10% faster with the
// larger pool.
constexpr uint32_t kDefaultPoolSize = 1u << 18;
constexpr uint32_t kDefaultCpuPoolSize = 1u << 15;
constexpr uint32_t kGpuPathsPerComputeUnit = 8192;

// Bounces a path may take when the command line names no bound. Unlimited,
// a path of throughput 1 (light trapped by total internal reflection in a
// glass ball: roulette never ends it) ran hundreds of thousands of bounces,
// one launch each on a global-queue schedule, and so set the render's time.
// Cut at 256, the bench scenes lose at most 2e-7 of their image mean
// (bench/results/path-length.md); tests of stiff furnaces ask for unlimited.
constexpr uint32_t kDefaultMaxDepth = 256;

struct RenderSettings {
    // Samples per pixel asked for, held here alone. In a progressive render
    // (render/progressive_render.h) 0 asks for no count: time, error or Ctrl-C end it.
    uint32_t spp = 16;
    uint32_t max_depth = kDefaultMaxDepth; // WF_UNLIMITED_DEPTH: ended by roulette alone
    uint32_t seed = 0;
    uint32_t pool_size = 0; // 0: chosen from the image and the device (render/device_renderer.h)
    // The first bounce count at which roulette may end a path; 5, chosen by
    // efficiency with Sobol points (bench/results/roulette-study.md).
    uint32_t roulette_depth = 5;
    float roulette_cap = 1.0f;   // the largest survival probability (kernels/stages/roulette.h)
    uint32_t local_size = 64; // at least WF_PATH_LENGTH_BUCKETS: accumulate counts with one work-item per bucket
    uint32_t light_sampling = WF_LIGHT_SAMPLING_MIS;
    uint32_t hemisphere = WF_HEMISPHERE_COSINE;
    // Chosen by efficiency, 1 / (relMSE x seconds): Sobol is 1.3-3.4x the
    // independent sampler on four bench scenes of five (bench/results/sampler-study.md).
    uint32_t sampler = WF_SAMPLER_SOBOL;
    uint32_t bounce_layers = 0; // per-bounce film layers, 0 for none
    uint32_t aovs = 0;          // WF_AOV_* bits: the first hit's layers (kernels/common/first_hit_aovs.h)
    bool specialize = true;     // compile the kernels for the scene's features (host/device/scene_features.h)
    std::string cache_dir;      // where compiled programs are kept (host/device/program_cache.h); empty: nowhere
    Integrator integrator = Integrator::Wavefront;
    Schedule schedule = Schedule::Auto; // for the wavefront integrator; the renderer resolves Auto
    QueuePush queue_push = QueuePush::Auto; // the renderer resolves Auto
    bool sort_materials = false; // reorder the extension queue by material before shade
    // The group schedule's BSDF lanes (kernels/stages/shade_lanes.h): 1 (none), 8
    // or 16 paths a work-item; 0: 8 on a device of 8-float vectors or wider,
    // else 1 (render/device_renderer.cpp). The same bytes at every width.
    uint32_t lane_width = 0;
    // Rays a work-item of the tracing stages traces at once
    // (kernels/geometry/trace_width.h): 1 or 2; 0: 2 on a CPU where the
    // scene's triangles outgrow the device's cache, else 1. The same bytes.
    uint32_t trace_width = 0;
    // Kernels of the wavefront's shade stage on a global-queue schedule
    // (include/wavefront/shade_record.h): 1 or 2; 0: 2 for a GPU's kernels,
    // else 1 (shade_in_two_kernels, path_integrator.h). The same bytes.
    uint32_t shade_kernels = 0;
    KernelKind kernels = KernelKind::Auto; // Auto: the device's kind
    // While it holds non-zero, no sample starts: the paths in flight end and
    // the round returns early, each slot's pixels then one sample apart at most.
    const std::atomic<int>* stop = nullptr;
};

// Whether a stop flag (RenderSettings::stop) is there and set.
inline bool stop_requested(const std::atomic<int>* stop) { return stop && stop->load() != 0; }

} // namespace wf
