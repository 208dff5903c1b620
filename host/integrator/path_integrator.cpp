// path_integrator.cpp — launches, counters and profiling, for both integrators.
#include "integrator/path_integrator.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "base/errors.h"

namespace wf {
namespace {

#define WF_STAGE_NAME(stage, kernel, queue) #kernel,
constexpr const char* kStageNames[STAGE_COUNT] = {WF_STAGES(WF_STAGE_NAME) "sort_by_material", "megakernel",
                                                  "group_wavefront"};
#undef WF_STAGE_NAME

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

double RenderStats::pool_occupancy() const {
    double traced = 0.0, slots = 0.0;
    for (const CounterSnapshot& c : counter_reads) {
        if (c.closest_rays == 0) continue;
        traced += whole_path_stage() != STAGE_COUNT ? c.busy_slots : c.closest_rays;
        slots += c.pool_size;
    }
    return slots > 0.0 ? traced / slots : 0.0;
}

void RenderStats::add(const RenderStats& o, bool with_counter_reads) {
    samples += o.samples;
    closest_rays += o.closest_rays;
    shadow_rays += o.shadow_rays;
    nonfinite_samples += o.nonfinite_samples;
    lane_paths += o.lane_paths;
    lane_slots += o.lane_slots;
    iterations += o.iterations;
    pool_size += o.pool_size;
    pool_bytes += o.pool_bytes;
    shade_record_bytes = std::max(shade_record_bytes, o.shade_record_bytes);
    for (int s = 0; s < STAGE_COUNT; ++s) {
        stages[s].seconds += o.stages[s].seconds;
        stages[s].launches += o.stages[s].launches;
    }
    for (int b = 0; b < WF_PATH_LENGTH_BUCKETS; ++b) path_lengths[b] += o.path_lengths[b];
    if (with_counter_reads) counter_reads.insert(counter_reads.end(), o.counter_reads.begin(), o.counter_reads.end());
}

RenderStats RenderStats::without_counter_reads() const {
    RenderStats copy;
    copy.integrator = integrator;
    copy.schedule = schedule;
    copy.seconds = seconds;
    copy.add(*this, false);
    return copy;
}

Stage RenderStats::whole_path_stage() const {
    if (integrator == Integrator::Megakernel) return STAGE_MEGAKERNEL;
    return schedule == Schedule::Group ? STAGE_GROUP : STAGE_COUNT;
}

uint32_t default_pool_size(const std::string& device_type, unsigned compute_units, Integrator integrator) {
    if (device_type == "cpu") return integrator == Integrator::Wavefront ? kDefaultCpuPoolSize : kDefaultPoolSize;
    return std::max(kDefaultPoolSize, std::min(compute_units, 1u << 12) * kGpuPathsPerComputeUnit);
}

Schedule default_schedule(const std::string& device_type, bool sort_materials) {
    return device_type == "cpu" && !sort_materials ? Schedule::Group : Schedule::Refill;
}

bool shade_in_two_kernels(const RenderSettings& settings) {
    if (settings.integrator != Integrator::Wavefront) return false;
    if (settings.schedule == Schedule::Auto || settings.kernels == KernelKind::Auto)
        throw std::logic_error("shade's kernels follow from a resolved schedule and kind of kernels");
    if (settings.schedule == Schedule::Group) return false;
    return settings.shade_kernels == 0 ? settings.kernels == KernelKind::Gpu : settings.shade_kernels == 2;
}

uint32_t choose_pool_size(uint32_t requested, uint32_t default_size, uint32_t pixel_count, std::string* note) {
    const uint32_t wanted = requested ? requested : default_size;
    const uint32_t size = std::min(wanted, pixel_count);
    if (requested && size != requested && note)
        *note = "pool size " + std::to_string(requested) + " capped at the pixel count, " +
                std::to_string(size) + ": each path slot traces whole pixels";
    return size;
}

uint32_t pool_that_fits(uint32_t pool, size_t device_memory, size_t max_allocation, size_t used_bytes,
                        bool shade_records) {
    const size_t room = device_memory > used_bytes ? (device_memory - used_bytes) / 2 : 0;
    const size_t fits = std::min(room / PathPool::bytes_per_path(shade_records),
                                 max_allocation / PathPool::largest_bytes_per_path(shade_records));
    return static_cast<uint32_t>(std::min<size_t>(pool, fits));
}

PathIntegrator::PathIntegrator(const OpenClDevice& device, const DeviceScene& scene, const Camera& camera,
                               const RenderSettings& settings)
    : device_(device), settings_(settings), scene_(scene), camera_(camera),
      pool_(device.context, settings.pool_size, shade_in_two_kernels(settings)),
      film_(device.context, device.queue, camera.width, camera.height, settings.bounce_layers, settings.aovs) {
    params_.pixel_count = camera.width * camera.height;
    params_.first_pixel = 0;
    params_.traced_pixels = params_.pixel_count;
    params_.pool_size = pool_.size();
    params_.max_depth = settings.max_depth;
    params_.seed = settings.seed;
    params_.roulette_depth = settings.roulette_depth;
    params_.roulette_cap = settings.roulette_cap;
    params_.light_count = scene.light_count;
    params_.light_sampling = settings.light_sampling;
    params_.hemisphere = settings.hemisphere;
    params_.sampler = settings.sampler;
    params_.bounce_layers = settings.bounce_layers;
    params_.aovs = settings.aovs;
    params_.environment_light = scene.environment_light;
    params_.scene_diameter = scene.scene_diameter;
    params_.environment = scene.environment;
    if (settings.pool_size == 0 || settings.pool_size > params_.pixel_count)
        throw std::logic_error("an integrator's pool must be chosen first (render/device_renderer.h)");
    if (settings.local_size < WF_PATH_LENGTH_BUCKETS)
        throw InputError("local size " + std::to_string(settings.local_size) + " is below " +
                         std::to_string(WF_PATH_LENGTH_BUCKETS) + ", the path-length histogram's buckets");
    stats_.integrator = settings.integrator;
    stats_.schedule = settings.schedule;
    stats_.pool_size = pool_.size();
    stats_.pool_bytes = pool_.bytes();
    stats_.shade_record_bytes = pool_.shade_records() ? PathPool::shade_record_bytes_per_path() : 0;
    for (int s = 0; s < STAGE_COUNT; ++s) stats_.stages[s].name = kStageNames[s];
    pool_.clear(device.queue); // every slot has started nothing
}

void PathIntegrator::launch(Stage stage, const cl::Kernel& kernel, uint32_t items) {
    const size_t local = settings_.local_size;
    const size_t global = (items + local - 1) / local * local;
    cl::Event event;
    device_.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(local), nullptr,
                                       &event);
    pending_.emplace_back(stage, event);
}

std::array<cl_uint, WF_COUNTER_COUNT> PathIntegrator::read_counters(uint32_t clear_from) {
    std::array<cl_uint, WF_COUNTER_COUNT> counters{};
    device_.queue.enqueueReadBuffer(pool_.counters, CL_TRUE, 0, sizeof(counters), counters.data());
    if (clear_from < WF_COUNTER_COUNT)
        device_.queue.enqueueFillBuffer(pool_.counters, 0u, clear_from * sizeof(cl_uint),
                                        (WF_COUNTER_COUNT - clear_from) * sizeof(cl_uint));
    CounterSnapshot snapshot;
    std::copy_n(counters.begin(), WF_QUEUE_COUNT, snapshot.queues.begin());
    snapshot.closest_rays = counters[WF_COUNTER_CLOSEST_RAYS];
    snapshot.shadow_rays = counters[WF_COUNTER_SHADOW_RAYS];
    snapshot.pool_size = pool_.size();
    snapshot.busy_slots = counters[WF_COUNTER_BUSY_SLOTS];
    for (int b = 0; b < WF_PATH_LENGTH_BUCKETS; ++b) {
        stats_.path_lengths[b] += counters[WF_COUNTER_PATH_LENGTHS + b];
        snapshot.samples += counters[WF_COUNTER_PATH_LENGTHS + b]; // every accumulated path is in one bucket
    }
    stats_.closest_rays += snapshot.closest_rays;
    stats_.shadow_rays += snapshot.shadow_rays;
    stats_.samples += snapshot.samples;
    stats_.nonfinite_samples += counters[WF_COUNTER_NONFINITE];
    stats_.lane_paths += counters[WF_COUNTER_LANE_PATHS];
    stats_.lane_slots += counters[WF_COUNTER_LANE_SLOTS];
    stats_.counter_reads.push_back(snapshot);
    ++stats_.iterations;
    for (const auto& [stage, event] : pending_) {
        stats_.stages[stage].seconds += event_seconds(event);
        ++stats_.stages[stage].launches;
    }
    pending_.clear();
    if (on_progress_) on_progress_(stats_);
    return counters;
}

void PathIntegrator::restore(const FilmState& film, const std::vector<uint32_t>& started) {
    film_.restore(device_.queue, film);
    pool_.restore_samples_started(device_.queue, started);
    samples_held_ = std::accumulate(started.begin(), started.end(), uint64_t{0});
    samples_counted_ = stats_.samples;
}

void PathIntegrator::trace_pixels(uint32_t first, const std::vector<uint32_t>& samples) {
    const auto count = static_cast<uint32_t>(samples.size());
    if (count == 0 || count > pool_.size() || uint64_t{first} + count > params_.pixel_count)
        throw std::logic_error("trace_pixels: " + std::to_string(count) + " pixels from " + std::to_string(first) +
                               " do not fit a pool of " + std::to_string(pool_.size()));
    params_.first_pixel = first;
    params_.traced_pixels = count;
    params_.pixel_list = 0;
    params_.pool_size = count;
    pool_.restore_samples_started(device_.queue, samples); // one pixel a slot: its samples are the slot's
    samples_held_ = std::accumulate(samples.begin(), samples.end(), uint64_t{0});
    samples_counted_ = stats_.samples;
}

void PathIntegrator::trace_pixel_list(const std::vector<uint32_t>& pixels, uint32_t samples) {
    const auto count = static_cast<uint32_t>(pixels.size());
    if (count == 0 || count > params_.pixel_count)
        throw std::logic_error("trace_pixel_list: " + std::to_string(count) + " pixels of " +
                               std::to_string(params_.pixel_count));
    pool_.set_pixel_list(device_.queue, pixels);
    params_.first_pixel = 0;
    params_.traced_pixels = count;
    params_.pixel_list = 1;
    params_.pool_size = std::min(count, pool_.size());
    // Slot i owns entries i, i + pool, ...; each has `samples` done, and the
    // slot takes a sample of each in turn, so it has started that many of each.
    std::vector<uint32_t> started(params_.pool_size);
    for (uint32_t slot = 0; slot < params_.pool_size; ++slot)
        started[slot] = ((count - 1 - slot) / params_.pool_size + 1) * samples;
    pool_.restore_samples_started(device_.queue, started);
    samples_held_ = uint64_t{count} * samples;
    samples_counted_ = stats_.samples;
}

void PathIntegrator::run_whole_paths(Stage stage, const cl::Kernel& kernel) {
    device_.queue.enqueueFillBuffer(pool_.counters, 0u, 0, WF_COUNTER_COUNT * sizeof(cl_uint));
    // Each launch finishes every sample it starts, so the traced pixels hold
    // what they held when set and what was traced since.
    const uint64_t wanted = uint64_t{params_.traced_pixels} * params_.spp;
    while (samples_held_ + (stats_.samples - samples_counted_) < wanted && !stopping()) {
        launch(stage, kernel, params_.pool_size);
        const uint64_t before = stats_.samples;
        read_counters(0); // the queues' counters too: the group schedule counts entries in them
        if (stats_.samples == before)
            throw std::logic_error(std::string(stats_.stages[stage].name) + ": a launch traced no sample");
    }
}

void PathIntegrator::queue_every_slot() {
    const uint32_t pool = params_.pool_size;
    std::vector<cl_uint> all_slots(pool);
    std::iota(all_slots.begin(), all_slots.end(), 0u);
    device_.queue.enqueueWriteBuffer(pool_.queues, CL_TRUE, sizeof(cl_uint) * WF_QUEUE_REGENERATE * size_t{pool},
                                     sizeof(cl_uint) * pool, all_slots.data());
    std::array<cl_uint, WF_COUNTER_COUNT> counters{};
    counters[WF_QUEUE_REGENERATE] = pool;
    device_.queue.enqueueWriteBuffer(pool_.counters, CL_TRUE, 0, sizeof(counters), counters.data());
}

} // namespace wf
