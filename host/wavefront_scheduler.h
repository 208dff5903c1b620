// wavefront_scheduler.h — the host loop that drives the stage kernels over the
// path pool until every pixel has its samples.
//
// One iteration:  generate → intersect → shade → intersect_shadow → roulette →
// accumulate, each launched over the queue it reads (sized from the counters
// read at the end of the previous iteration), then one read of the counters.
// Freed slots are refilled by generate at the start of the next iteration, so
// the pool stays full until the last samples of a round are started.
//
// A render is a sequence of rounds, each taking every pixel to a target
// sample count; between rounds the film can be read. Since a pixel's samples
// are traced one after another by its owning slot, the rounds change nothing
// in the image: N samples in one round or in ten give the same bytes.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "device_scene.h"
#include "film.h"
#include "opencl_device.h"
#include "path_pool.h"
#include "wavefront/path_state.h"
#include "wavefront/scene_types.h"

namespace wf {

struct RenderSettings {
    uint32_t spp = 16;
    uint32_t max_depth = WF_UNLIMITED_DEPTH;
    uint32_t seed = 0;
    uint32_t pool_size = 0; // 0: chosen from the image and the device
    uint32_t roulette_depth = 3;
    uint32_t local_size = 64; // at least WF_PATH_LENGTH_BUCKETS: accumulate counts with one work-item per bucket
    uint32_t light_sampling = WF_LIGHT_SAMPLING_MIS;
    uint32_t hemisphere = WF_HEMISPHERE_COSINE;
    uint32_t sampler = WF_SAMPLER_INDEPENDENT;
    uint32_t bounce_layers = 0; // per-bounce film layers, 0 for none
    bool specialize = true;     // compile the kernels for the scene's features (host/scene_features.h)
    std::string cache_dir;      // where compiled programs are kept (host/program_cache.h); empty: nowhere
};

enum Stage { STAGE_GENERATE, STAGE_INTERSECT, STAGE_SHADE, STAGE_INTERSECT_SHADOW, STAGE_ROULETTE, STAGE_ACCUMULATE, STAGE_COUNT };

struct StageTime {
    const char* name = "";
    double seconds = 0.0; // from OpenCL profiling events
    uint64_t launches = 0;
};

struct RenderStats {
    double seconds = 0.0; // wall time spent in render_to()
    uint64_t samples = 0;
    uint64_t closest_rays = 0;
    uint64_t shadow_rays = 0;
    uint64_t nonfinite_samples = 0;
    uint64_t iterations = 0;
    uint32_t pool_size = 0;
    size_t pool_bytes = 0;
    std::array<StageTime, STAGE_COUNT> stages{};
    // Finished paths by bounces: bucket 0 holds 0, bucket b ≥ 1 holds [2^(b−1), 2^b), the last open-ended.
    std::array<uint64_t, WF_PATH_LENGTH_BUCKETS> path_lengths{};
    double kernel_seconds() const;
};

// The pool size used for a render: the requested one (or a default), never more
// than the pixel count, since each slot owns whole pixels. `note` says why when
// it differs from the request.
uint32_t choose_pool_size(uint32_t requested, uint32_t pixel_count, std::string* note);

class WavefrontScheduler {
public:
    WavefrontScheduler(const OpenClDevice& device, const cl::Program& program, const DeviceScene& scene,
                       const Camera& camera, const RenderSettings& settings);

    // Continues every pixel up to `spp` samples (a round).
    void render_to(uint32_t spp);

    const RenderStats& stats() const { return stats_; }
    const Film& film() const { return film_; }

private:
    cl::Event launch(Stage stage, uint32_t items);
    void set_stage_args();

    const OpenClDevice& device_;
    RenderSettings settings_;
    RenderParams params_{};
    const DeviceScene& scene_;
    Camera camera_;
    PathPool pool_;
    Film film_;
    std::array<cl::Kernel, STAGE_COUNT> kernels_;
    RenderStats stats_;
};

} // namespace wf
