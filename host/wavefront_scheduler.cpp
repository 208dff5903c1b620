// wavefront_scheduler.cpp — launches, counters and profiling of the wavefront.
#include "wavefront_scheduler.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <vector>

namespace wf {
namespace {

constexpr const char* kStageNames[STAGE_COUNT] = {"generate", "intersect", "shade",
                                                  "intersect_shadow", "roulette", "accumulate"};
constexpr uint32_t kDefaultPoolSize = 1u << 18;

double event_seconds(const cl::Event& e) {
    const cl_ulong start = e.getProfilingInfo<CL_PROFILING_COMMAND_START>();
    const cl_ulong end = e.getProfilingInfo<CL_PROFILING_COMMAND_END>();
    return 1e-9 * static_cast<double>(end - start);
}

} // namespace

double RenderStats::kernel_seconds() const {
    return std::accumulate(stages.begin(), stages.end(), 0.0,
                           [](double s, const StageTime& t) { return s + t.seconds; });
}

uint32_t choose_pool_size(uint32_t requested, uint32_t pixel_count, std::string* note) {
    const uint32_t wanted = requested ? requested : kDefaultPoolSize;
    const uint32_t size = std::min(wanted, pixel_count);
    if (requested && size != requested && note)
        *note = "pool size " + std::to_string(requested) + " capped at the pixel count, " +
                std::to_string(size) + ": each path slot traces whole pixels";
    return size;
}

WavefrontScheduler::WavefrontScheduler(const OpenClDevice& device, const cl::Program& program,
                                       const DeviceScene& scene, const Camera& camera,
                                       const RenderSettings& settings)
    : device_(device), settings_(settings),
      pool_(device.context, choose_pool_size(settings.pool_size, camera.width * camera.height, nullptr)),
      film_(device.context, device.queue, camera.width, camera.height) {
    params_.pixel_count = camera.width * camera.height;
    params_.pool_size = pool_.size();
    params_.spp = settings.spp;
    params_.max_depth = settings.max_depth;
    params_.seed = settings.seed;
    params_.roulette_depth = settings.roulette_depth;
    params_.light_count = scene.light_count;

    for (int s = 0; s < STAGE_COUNT; ++s) {
        kernels_[s] = cl::Kernel(program, kStageNames[s]);
        pool_.set_stage_args(kernels_[s], params_);
    }
    auto stage_arg = [this](Stage s) { return pool_.set_stage_args(kernels_[s], params_); };
    kernels_[STAGE_GENERATE].setArg(stage_arg(STAGE_GENERATE), camera);
    for (Stage s : {STAGE_INTERSECT, STAGE_INTERSECT_SHADOW}) {
        const cl_uint i = stage_arg(s);
        kernels_[s].setArg(i, scene.nodes);
        kernels_[s].setArg(i + 1, scene.triangles);
    }
    {
        const cl_uint i = stage_arg(STAGE_SHADE);
        kernels_[STAGE_SHADE].setArg(i, scene.triangles);
        kernels_[STAGE_SHADE].setArg(i + 1, scene.normals);
        kernels_[STAGE_SHADE].setArg(i + 2, scene.materials);
        kernels_[STAGE_SHADE].setArg(i + 3, scene.lights);
    }
    {
        const cl_uint i = stage_arg(STAGE_ACCUMULATE);
        kernels_[STAGE_ACCUMULATE].setArg(i, film_.sum);
        kernels_[STAGE_ACCUMULATE].setArg(i + 1, film_.compensation);
        kernels_[STAGE_ACCUMULATE].setArg(i + 2, film_.samples);
    }
}

cl::Event WavefrontScheduler::launch(Stage stage, uint32_t items) {
    const size_t local = settings_.local_size;
    const size_t global = (items + local - 1) / local * local;
    cl::Event event;
    device_.queue.enqueueNDRangeKernel(kernels_[stage], cl::NullRange, cl::NDRange(global),
                                       cl::NDRange(local), nullptr, &event);
    return event;
}

RenderStats WavefrontScheduler::render() {
    const auto start = std::chrono::steady_clock::now();
    const cl::CommandQueue& queue = device_.queue;
    const uint32_t pool = pool_.size();
    RenderStats stats;
    stats.pool_size = pool;
    stats.pool_bytes = pool_.bytes();
    for (int s = 0; s < STAGE_COUNT; ++s) stats.stages[s].name = kStageNames[s];

    // Every slot starts free: the regeneration queue holds them all.
    std::vector<cl_uint> all_slots(pool);
    std::iota(all_slots.begin(), all_slots.end(), 0u);
    queue.enqueueWriteBuffer(pool_.queues, CL_FALSE, sizeof(cl_uint) * WF_QUEUE_REGENERATE * size_t{pool},
                             sizeof(cl_uint) * pool, all_slots.data());
    std::array<cl_uint, WF_COUNTER_COUNT> counters{};
    counters[WF_QUEUE_REGENERATE] = pool;
    queue.enqueueWriteBuffer(pool_.counters, CL_FALSE, 0, sizeof(counters), counters.data());
    pool_.clear(queue); // every slot has started nothing

    std::vector<std::pair<Stage, cl::Event>> events;
    uint32_t extending = 0, regenerating = pool;
    while (extending + regenerating > 0) {
        const uint32_t active = std::min(pool, extending + regenerating);
        events.clear();
        if (regenerating) events.emplace_back(STAGE_GENERATE, launch(STAGE_GENERATE, regenerating));
        events.emplace_back(STAGE_INTERSECT, launch(STAGE_INTERSECT, active));
        events.emplace_back(STAGE_SHADE, launch(STAGE_SHADE, active));
        queue.enqueueFillBuffer(pool_.counters, 0u, 0, 2 * sizeof(cl_uint)); // EXTEND, REGENERATE
        events.emplace_back(STAGE_INTERSECT_SHADOW, launch(STAGE_INTERSECT_SHADOW, active));
        events.emplace_back(STAGE_ROULETTE, launch(STAGE_ROULETTE, active));
        events.emplace_back(STAGE_ACCUMULATE, launch(STAGE_ACCUMULATE, active));
        queue.enqueueReadBuffer(pool_.counters, CL_TRUE, 0, sizeof(counters), counters.data());
        queue.enqueueFillBuffer(pool_.counters, 0u, 2 * sizeof(cl_uint), (WF_COUNTER_COUNT - 2) * sizeof(cl_uint));

        extending = counters[WF_QUEUE_EXTEND];
        regenerating = counters[WF_QUEUE_REGENERATE];
        stats.closest_rays += counters[WF_COUNTER_CLOSEST_RAYS];
        stats.shadow_rays += counters[WF_COUNTER_SHADOW_RAYS];
        stats.nonfinite_samples += counters[WF_COUNTER_NONFINITE];
        stats.samples += counters[WF_QUEUE_FINISHED];
        ++stats.iterations;
        for (const auto& [stage, event] : events) {
            stats.stages[stage].seconds += event_seconds(event);
            ++stats.stages[stage].launches;
        }
    }
    queue.finish();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

} // namespace wf
