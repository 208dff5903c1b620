// path_integrator.h — what both integrators share: the render settings and
// statistics, the path pool and the film on the device, kernel launches timed
// by profiling events, and the counters the kernels keep.
//
// Two integrators run the same stage functions (kernels/stages/) and give the
// same bytes for the same seed:
//   WavefrontIntegrator (wavefront_integrator.h): one kernel per stage, over queues;
//   MegakernelIntegrator (megakernel_integrator.h): one kernel takes each path
//   through every stage.
// A render is a sequence of rounds, each taking every pixel to a target sample
// count; between rounds the film can be read. Since a pixel's samples are
// traced one after another by its owning slot, the rounds change nothing in
// the image: N samples in one round or in ten give the same bytes.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "device/device_scene.h"
#include "film/film.h"
#include "device/opencl_device.h"
#include "integrator/path_pool.h"
#include "integrator/render_settings.h"
#include "integrator/stage_args.h"
#include "wavefront/counters.h"
#include "wavefront/render_params.h"
#include "wavefront/stage_graph.h"
#include "wavefront/scene_types.h"

namespace wf {

// The stage kernels of the stage list (wavefront/stage_graph.h), then the
// kernels that time several stages at once.
#define WF_STAGE_ENUM(stage, kernel, queue) STAGE_##stage,
enum Stage {
    WF_STAGES(WF_STAGE_ENUM)
    STAGE_SORT, // --sort-materials: three kernels (kernels/stages/sort_by_material.h)
    STAGE_MEGAKERNEL,
    STAGE_GROUP, // --schedule group: every stage in one kernel (group_wavefront)
    STAGE_COUNT
};
#undef WF_STAGE_ENUM
constexpr int kStageKernels = STAGE_SORT; // the stage list's

// The queue each stage of the list consumes.
#define WF_STAGE_QUEUE(stage, kernel, queue) WF_QUEUE_##queue,
constexpr QueueId kStageQueue[kStageKernels] = {WF_STAGES(WF_STAGE_QUEUE)};
#undef WF_STAGE_QUEUE

struct StageTime {
    const char* name = "";
    double seconds = 0.0; // from OpenCL profiling events
    uint64_t launches = 0;
};

// What one read of the device counters showed: the queue lengths as read
// (global-queue schedules), or the paths that entered each queue since the
// previous read (the group schedule, whose queues are local: its launch
// counts them; the megakernel has none), and the work done since then.
struct CounterSnapshot {
    std::array<uint32_t, WF_QUEUE_COUNT> queues{};
    uint32_t closest_rays = 0, shadow_rays = 0, samples = 0;
    uint32_t pool_size = 0; // of the pool read
    uint32_t busy_slots = 0; // those that started a sample, where one launch takes paths camera to film

    // As a row of the statistics' table (the stats JSON, the Python module),
    // in the order kColumns names: the queue lengths as read (the stage
    // graph's queues), then the work done since the previous read.
#define WF_QUEUE_NAME(queue, name, what) name,
    static constexpr std::array<const char*, WF_QUEUE_COUNT + 3> kColumns = {
        WF_QUEUES(WF_QUEUE_NAME) "closest_rays", "shadow_rays", "samples"};
#undef WF_QUEUE_NAME
    std::array<uint32_t, kColumns.size()> row() const {
        std::array<uint32_t, kColumns.size()> r{};
        std::copy(queues.begin(), queues.end(), r.begin());
        r[WF_QUEUE_COUNT] = closest_rays;
        r[WF_QUEUE_COUNT + 1] = shadow_rays;
        r[WF_QUEUE_COUNT + 2] = samples;
        return r;
    }
};

struct RenderStats {
    Integrator integrator = Integrator::Wavefront;
    Schedule schedule = Schedule::Refill;
    double seconds = 0.0; // wall time spent in render_to()
    uint64_t samples = 0;
    uint64_t closest_rays = 0;
    uint64_t shadow_rays = 0;
    uint64_t nonfinite_samples = 0;
    uint64_t lane_paths = 0, lane_slots = 0; // the group schedule's BSDF lanes: paths in them, lanes taken
    uint64_t iterations = 0; // reads of the counters: wavefront iterations or steps, megakernel launches
    uint32_t pool_size = 0;
    size_t pool_bytes = 0;
    size_t shade_record_bytes = 0; // a path, where the render keeps shade records (shade_in_two_kernels)
    std::array<StageTime, STAGE_COUNT> stages{};
    // Finished paths by bounces: bucket 0 holds 0, bucket b ≥ 1 holds [2^(b−1), 2^b), the last open-ended.
    std::array<uint64_t, WF_PATH_LENGTH_BUCKETS> path_lengths{};
    std::vector<CounterSnapshot> counter_reads; // one per iteration
    double kernel_seconds() const;
    // Mean share of the pool traced by each launch of the closest-hit work:
    // its closest rays, or where one kernel takes paths from camera to film,
    // its slots that started a sample (a group launch's may start several).
    double pool_occupancy() const;
    // Adds another device's counts and kernel times (a render over several
    // devices), and its counter reads if asked; leaves the time.
    void add(const RenderStats& other, bool with_counter_reads);
    // A copy without the counter reads, which grow all render long: what a
    // progress report or another rank needs.
    RenderStats without_counter_reads() const;
    // The stage whose one kernel takes paths from the camera to the film (the
    // megakernel, --schedule group), or STAGE_COUNT where each stage is a kernel.
    Stage whole_path_stage() const;
};

// The default pool for a device of this type ("cpu", "gpu", ...; DeviceInfo::type),
// compute units and integrator (render_settings.h says why).
uint32_t default_pool_size(const std::string& device_type, unsigned compute_units, Integrator integrator);

// The schedule a wavefront render runs when none is asked for: on a CPU,
// group, whose stages keep a work-group's paths in one core's caches (the
// fastest there, docs/scheduling.md); elsewhere, and to sort by material
// (which needs the global queue), refill.
Schedule default_schedule(const std::string& device_type, bool sort_materials);

// Whether a render runs shade as two kernels, surface then shade, with a
// record a path between them (include/wavefront/shade_record.h): as
// --shade-kernels says, by default a GPU's program, where one kernel's
// registers cost occupancy (bench/results/gpu-isa.md); a CPU's would only pay
// for the record's memory. Only the global-queue schedules: the megakernel
// and the group schedule keep a path in one kernel. `settings` resolved: a
// schedule and a kind of kernels (render/device_renderer.h), else logic_error.
bool shade_in_two_kernels(const RenderSettings& settings);

// The pool size used for a render: the requested one (or `default_size`),
// never more than the pixel count, since each slot owns whole pixels. `note`
// says why when it differs from the request.
uint32_t choose_pool_size(uint32_t requested, uint32_t default_size, uint32_t pixel_count, std::string* note);

// `pool`, or fewer paths where they would take more than half the memory that
// `used_bytes` (scene and image) leave, or a larger buffer than one allocation
// may be (PathPool::largest_bytes_per_path); 0 when not even one path fits.
uint32_t pool_that_fits(uint32_t pool, size_t device_memory, size_t max_allocation, size_t used_bytes,
                        bool shade_records);

class PathIntegrator {
public:
    virtual ~PathIntegrator() = default;

    // Continues every pixel up to `round_spp` samples (a round), unless
    // settings.stop ends it early.
    virtual void render_to(uint32_t round_spp) = 0;

    const RenderStats& stats() const { return stats_; }
    const Film& film() const { return film_; }
    Film& film() { return film_; }
    PathPool& pool() { return pool_; }

    // Goes on from a stopped render: its film, and the samples each slot had
    // started (which a stopped render has also finished).
    void restore(const FilmState& film, const std::vector<uint32_t>& started);
    // From the next round on, traces pixels [first, first + samples.size()),
    // one slot each, going on from `samples` (what the film holds of them):
    // a unit of work of a render over several devices (render/renderer.h).
    // The film's sums of those pixels must be current on this device.
    void trace_pixels(uint32_t first, const std::vector<uint32_t>& samples);
    // From the next round on, traces the listed pixels, each of which has
    // `samples` samples: adaptive sampling's unfinished pixels
    // (render/adaptive_sampling.h). The slots take them as they take a run.
    void trace_pixel_list(const std::vector<uint32_t>& pixels, uint32_t samples);

    // Called after every read of the counters (a progress display).
    void on_progress(std::function<void(const RenderStats&)> f) { on_progress_ = std::move(f); }

protected:
    PathIntegrator(const OpenClDevice& device, const DeviceScene& scene, const Camera& camera,
                   const RenderSettings& settings);

    // What every kernel's shared parameters are bound to (stage_args.h).
    StageArgs stage_args() const { return StageArgs{pool_, params_, camera_, scene_, film_}; }
    // Enqueues `kernel` over `items` work-items, rounded up to whole
    // work-groups; its time is added to `stage` at the next read_counters().
    void launch(Stage stage, const cl::Kernel& kernel, uint32_t items);
    // Waits for the device and reads every counter; adds the statistics to
    // stats_ and records a snapshot; then zeroes counters [clear_from, end) on
    // the device. Returns the counters as read.
    std::array<cl_uint, WF_COUNTER_COUNT> read_counters(uint32_t clear_from);
    // Every slot to the regeneration queue, the other counters to zero: the start of a round.
    void queue_every_slot();
    // Launches `kernel`, which takes one sample (the megakernel) or a few
    // (--schedule group) of every slot that has samples left through their
    // whole paths, until every pixel has params_.spp samples or the render is stopped.
    void run_whole_paths(Stage stage, const cl::Kernel& kernel);
    bool stopping() const { return stop_requested(settings_.stop); }

    const OpenClDevice& device_;
    RenderSettings settings_;
    RenderParams params_{};
    const DeviceScene& scene_;
    Camera camera_;
    PathPool pool_;
    Film film_;
    RenderStats stats_;
    // Samples the traced pixels held when they were set (restore(),
    // trace_pixels()), and stats_.samples then: the difference to now is traced.
    uint64_t samples_held_ = 0, samples_counted_ = 0;

private:
    std::vector<std::pair<Stage, cl::Event>> pending_; // launched since the last read
    std::function<void(const RenderStats&)> on_progress_;
};

} // namespace wf
