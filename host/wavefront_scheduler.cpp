// wavefront_scheduler.cpp — launches, counters and profiling of the wavefront.
#include "wavefront_scheduler.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <vector>

#include "errors.h"

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
    : device_(device), settings_(settings), scene_(scene), camera_(camera),
      pool_(device.context, choose_pool_size(settings.pool_size, camera.width * camera.height, nullptr)),
      film_(device.context, device.queue, camera.width, camera.height, settings.bounce_layers) {
    params_.pixel_count = camera.width * camera.height;
    params_.pool_size = pool_.size();
    params_.max_depth = settings.max_depth;
    params_.seed = settings.seed;
    params_.roulette_depth = settings.roulette_depth;
    params_.light_count = scene.light_count;
    params_.light_sampling = settings.light_sampling;
    params_.hemisphere = settings.hemisphere;
    params_.sampler = settings.sampler;
    params_.bounce_layers = settings.bounce_layers;
    params_.environment_light = scene.environment_light;
    params_.scene_diameter = scene.scene_diameter;
    params_.environment = scene.environment.header;
    if (settings.local_size < WF_PATH_LENGTH_BUCKETS)
        throw InputError("local size " + std::to_string(settings.local_size) + " is below " +
                         std::to_string(WF_PATH_LENGTH_BUCKETS) + ", the path-length histogram's buckets");
    for (int s = 0; s < STAGE_COUNT; ++s) kernels_[s] = cl::Kernel(program, kStageNames[s]);
    stats_.pool_size = pool_.size();
    stats_.pool_bytes = pool_.bytes();
    for (int s = 0; s < STAGE_COUNT; ++s) stats_.stages[s].name = kStageNames[s];
    pool_.clear(device.queue); // every slot has started nothing
}

// Sets consecutive arguments of `kernel` from index `first` on.
template <class... Args> void set_kernel_args(cl::Kernel& kernel, cl_uint first, const Args&... args) {
    (kernel.setArg(first++, args), ...);
}

// Every kernel's arguments: the shared ones (WF_STAGE_PARAMS), then its own.
// The render constants change from round to round.
void WavefrontScheduler::set_stage_args() {
    auto shared_then = [this](Stage s) -> cl::Kernel& {
        cl::Kernel& k = kernels_[s];
        pool_.set_stage_args(k, params_);
        return k;
    };
    const cl_uint own = PathPool::kSharedStageArgs;
    set_kernel_args(shared_then(STAGE_GENERATE), own, camera_);
    cl::Kernel& intersect = shared_then(STAGE_INTERSECT);
    set_kernel_args(intersect, own, scene_.nodes, scene_.triangles);
    set_texture_args(intersect, own + 2, scene_.textures);
    cl::Kernel& shade = shared_then(STAGE_SHADE);
    set_kernel_args(shade, own, scene_.triangles, scene_.normals, scene_.materials, scene_.lights, scene_.punctual,
                    scene_.environment.texels, scene_.environment.distribution);
    set_kernel_args(shade, set_texture_args(shade, own + 7, scene_.textures), film_.layers,
                    film_.layer_compensation);
    cl::Kernel& shadow = shared_then(STAGE_INTERSECT_SHADOW);
    set_kernel_args(shadow, own, scene_.nodes, scene_.triangles);
    set_kernel_args(shadow, set_texture_args(shadow, own + 2, scene_.textures), film_.layers,
                    film_.layer_compensation);
    shared_then(STAGE_ROULETTE);
    set_kernel_args(shared_then(STAGE_ACCUMULATE), own, film_.sum, film_.compensation, film_.sum_squares,
                    film_.squares_compensation, film_.samples);
}

cl::Event WavefrontScheduler::launch(Stage stage, uint32_t items) {
    const size_t local = settings_.local_size;
    const size_t global = (items + local - 1) / local * local;
    cl::Event event;
    device_.queue.enqueueNDRangeKernel(kernels_[stage], cl::NullRange, cl::NDRange(global),
                                       cl::NDRange(local), nullptr, &event);
    return event;
}

void WavefrontScheduler::render_to(uint32_t spp) {
    const auto start = std::chrono::steady_clock::now();
    const cl::CommandQueue& queue = device_.queue;
    const uint32_t pool = pool_.size();
    params_.spp = spp;
    set_stage_args();

    // Every slot goes to the regeneration queue; those whose pixels already
    // have `spp` samples start nothing and drop out at once.
    std::vector<cl_uint> all_slots(pool);
    std::iota(all_slots.begin(), all_slots.end(), 0u);
    queue.enqueueWriteBuffer(pool_.queues, CL_FALSE, sizeof(cl_uint) * WF_QUEUE_REGENERATE * size_t{pool},
                             sizeof(cl_uint) * pool, all_slots.data());
    std::array<cl_uint, WF_COUNTER_COUNT> counters{};
    counters[WF_QUEUE_REGENERATE] = pool;
    queue.enqueueWriteBuffer(pool_.counters, CL_FALSE, 0, sizeof(counters), counters.data());

    std::vector<std::pair<Stage, cl::Event>> events;
    uint32_t extending = 0, regenerating = pool;
    while (extending + regenerating > 0) {
        const uint32_t active = std::min(pool, extending + regenerating);
        events.clear();
        if (regenerating) events.emplace_back(STAGE_GENERATE, launch(STAGE_GENERATE, regenerating));
        events.emplace_back(STAGE_INTERSECT, launch(STAGE_INTERSECT, active));
        events.emplace_back(STAGE_SHADE, launch(STAGE_SHADE, active));
        queue.enqueueFillBuffer(pool_.counters, 0u, 0, 2 * sizeof(cl_uint)); // EXTEND, REGENERATE
        // The queues shade filled, read before their stages so that each is
        // launched at its own length, and not at all when empty (a scene
        // without lights never launches intersect_shadow). Roulette moves
        // some of its paths to the finished queue, so accumulate is sized
        // for both; its kernel stops at the queue's final length.
        queue.enqueueReadBuffer(pool_.counters, CL_TRUE, WF_QUEUE_SHADOW * sizeof(cl_uint), 3 * sizeof(cl_uint),
                                &counters[WF_QUEUE_SHADOW]);
        const uint32_t shadowed = counters[WF_QUEUE_SHADOW], continuing = counters[WF_QUEUE_CONTINUE];
        const uint32_t finishing = counters[WF_QUEUE_FINISHED] + continuing;
        if (shadowed) events.emplace_back(STAGE_INTERSECT_SHADOW, launch(STAGE_INTERSECT_SHADOW, shadowed));
        if (continuing) events.emplace_back(STAGE_ROULETTE, launch(STAGE_ROULETTE, continuing));
        if (finishing) events.emplace_back(STAGE_ACCUMULATE, launch(STAGE_ACCUMULATE, finishing));
        queue.enqueueReadBuffer(pool_.counters, CL_TRUE, 0, sizeof(counters), counters.data());
        queue.enqueueFillBuffer(pool_.counters, 0u, 2 * sizeof(cl_uint), (WF_COUNTER_COUNT - 2) * sizeof(cl_uint));

        extending = counters[WF_QUEUE_EXTEND];
        regenerating = counters[WF_QUEUE_REGENERATE];
        stats_.closest_rays += counters[WF_COUNTER_CLOSEST_RAYS];
        stats_.shadow_rays += counters[WF_COUNTER_SHADOW_RAYS];
        stats_.nonfinite_samples += counters[WF_COUNTER_NONFINITE];
        stats_.samples += counters[WF_QUEUE_FINISHED];
        for (int b = 0; b < WF_PATH_LENGTH_BUCKETS; ++b) stats_.path_lengths[b] += counters[WF_COUNTER_PATH_LENGTHS + b];
        ++stats_.iterations;
        for (const auto& [stage, event] : events) {
            stats_.stages[stage].seconds += event_seconds(event);
            ++stats_.stages[stage].launches;
        }
    }
    queue.finish();
    stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace wf
