// wavefront_integrator.cpp — the three schedules of the stage kernels.
#include "integrator/wavefront_integrator.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace wf {

WavefrontIntegrator::WavefrontIntegrator(const OpenClDevice& device, const cl::Program& program,
                                        const DeviceScene& scene, const Camera& camera,
                                        const RenderSettings& settings)
    : PathIntegrator(device, scene, camera, settings) {
    for (int s = 0; s < kStageKernels; ++s) kernels_[s] = cl::Kernel(program, stats_.stages[s].name);
    if (settings.schedule == Schedule::Group) group_ = cl::Kernel(program, stats_.stages[STAGE_GROUP].name);
    if (pool_.shade_records()) surface_ = cl::Kernel(program, "surface");
    if (settings.sort_materials) {
        count_materials_ = cl::Kernel(program, "count_materials");
        scan_materials_ = cl::Kernel(program, "scan_materials");
        scatter_materials_ = cl::Kernel(program, "scatter_materials");
        key_counts_ = cl::Buffer(device.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * WF_SORT_KEYS);
        sorted_ = cl::Buffer(device.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * size_t{pool_.size()});
        device.queue.enqueueFillBuffer(key_counts_, 0u, 0, sizeof(cl_uint) * WF_SORT_KEYS);
    }
}

void WavefrontIntegrator::extend(uint32_t items) {
    for (int s = 0; s < kStageKernels; ++s) {
        if (kStageQueue[s] != WF_QUEUE_EXTEND) continue;
        if (s == STAGE_SHADE && settings_.sort_materials) sort_by_material(items);
        // Shade's first kernel, timed as the stage's (include/wavefront/shade_record.h).
        if (s == STAGE_SHADE && surface_()) PathIntegrator::launch(STAGE_SHADE, surface_, items);
        launch(static_cast<Stage>(s), items);
    }
}

void WavefrontIntegrator::sort_by_material(uint32_t items) {
    PathIntegrator::launch(STAGE_SORT, count_materials_, items);
    PathIntegrator::launch(STAGE_SORT, scan_materials_, 1);
    PathIntegrator::launch(STAGE_SORT, scatter_materials_, items);
    // The extension queue is the first region of the queue buffer.
    device_.queue.enqueueCopyBuffer(sorted_, pool_.queues, 0, 0, sizeof(cl_uint) * size_t{items});
    device_.queue.enqueueFillBuffer(key_counts_, 0u, 0, sizeof(cl_uint) * WF_SORT_KEYS);
}

// Every kernel's arguments: the shared ones (stage_args.h), then shade's
// records and the sort's own. The render constants change from round to round.
void WavefrontIntegrator::set_stage_args() {
    const StageArgs shared = stage_args();
    cl_uint own = 0; // a kernel's first argument of its own
    for (cl::Kernel& k : kernels_) own = wf::set_stage_args(k, shared);
    if (settings_.schedule == Schedule::Group) wf::set_stage_args(group_, shared);
    if (surface_()) {
        wf::set_stage_args(surface_, shared);
        set_kernel_args(surface_, own, pool_.shade_records);
        set_kernel_args(kernels_[STAGE_SHADE], own, pool_.shade_records);
    }
    if (settings_.sort_materials) {
        set_kernel_args(count_materials_, wf::set_stage_args(count_materials_, shared), key_counts_);
        set_kernel_args(scan_materials_, 0, key_counts_);
        set_kernel_args(scatter_materials_, wf::set_stage_args(scatter_materials_, shared), key_counts_, sorted_);
    }
}

void WavefrontIntegrator::render_to(uint32_t round_spp) {
    const auto start = std::chrono::steady_clock::now();
    params_.spp = round_spp;
    set_stage_args();
    if (settings_.schedule == Schedule::Group) {
        run_whole_paths(STAGE_GROUP, group_); // its queues are the work-groups' own
    } else {
        // Every slot goes to the regeneration queue; those whose pixels already
        // have `round_spp` samples start nothing and drop out at once.
        queue_every_slot();
        if (settings_.schedule == Schedule::Fullest) run_fullest_first();
        else run_iterations(settings_.schedule == Schedule::Passes);
    }
    device_.queue.finish();
    stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Refill and passes, each iteration in two phases. First the stages that
// take the free slots (generate) and the extension queue (intersect, shade).
// Then the queues these filled, the later queues of the list (from
// WF_QUEUE_SHADOW on), are read, and each stage that takes one is launched in
// the list's order, at its queue's length plus the lengths launched before it
// in this phase: a stage may pass its paths on to a later one (intersect_shadow
// to roulette or accumulate, roulette to accumulate), whose kernel stops at
// its queue's final length. An empty launch is left out (a scene without
// lights never launches intersect_shadow). So the loop follows the stage list,
// and a stage added to it is launched here without a line of its own.
void WavefrontIntegrator::run_iterations(bool passes) {
    static_assert(WF_QUEUE_EXTEND == 0 && WF_QUEUE_REGENERATE == 1 && kLaterQueue == 2,
                  "the first phase's queues, [EXTEND, REGENERATE], are cleared with one fill");
    const cl::CommandQueue& queue = device_.queue;
    const uint32_t pool = params_.pool_size;
    uint32_t extending = 0, regenerating = pool;
    for (;;) {
        const bool stop = stopping(); // read once: it may change at any time
        if (extending + (stop ? 0u : regenerating) == 0) break;
        const bool generating = regenerating > 0 && !(passes && extending > 0) && !stop;
        if (generating) launch(consumer_of(WF_QUEUE_REGENERATE), regenerating);
        extend(std::min(pool, extending + (generating ? regenerating : 0u)));
        // Shade consumed EXTEND and generate REGENERATE; passes keep the
        // slots freed so far in REGENERATE until the pass ends.
        queue.enqueueFillBuffer(pool_.counters, 0u, 0, (generating ? 2 : 1) * sizeof(cl_uint));
        std::array<cl_uint, WF_QUEUE_COUNT> queued{};
        queue.enqueueReadBuffer(pool_.counters, CL_TRUE, kLaterQueue * sizeof(cl_uint),
                                (WF_QUEUE_COUNT - kLaterQueue) * sizeof(cl_uint), &queued[kLaterQueue]);
        uint32_t reaching = 0;
        for (int s = 0; s < kStageKernels; ++s) {
            if (kStageQueue[s] < kLaterQueue) continue;
            reaching += queued[kStageQueue[s]];
            if (reaching) launch(static_cast<Stage>(s), reaching);
        }
        const auto counters = read_counters(kLaterQueue); // the queues consumed above, and the statistics
        extending = counters[WF_QUEUE_EXTEND];
        regenerating = counters[WF_QUEUE_REGENERATE];
    }
}

// Fullest first. Each queue has one consumer (EXTEND two: intersect, then
// shade over the same slots), which takes it whole; its counter is then
// zeroed. Ties go to the later stage, which brings paths nearer their end:
// the queues in the reverse of the order the stage list consumes them.
void WavefrontIntegrator::run_fullest_first() {
    std::vector<int> later_first;
    for (int s = kStageKernels - 1; s >= 0; --s)
        if (std::find(later_first.begin(), later_first.end(), kStageQueue[s]) == later_first.end())
            later_first.push_back(kStageQueue[s]);
    std::array<cl_uint, WF_COUNTER_COUNT> counters{};
    counters[WF_QUEUE_REGENERATE] = params_.pool_size;
    for (;;) {
        int fullest = later_first[0];
        if (stopping()) counters[WF_QUEUE_REGENERATE] = 0; // start nothing more
        for (int q : later_first)
            if (counters[q] > counters[fullest]) fullest = q;
        const uint32_t items = counters[fullest];
        if (items == 0) break;
        if (fullest == WF_QUEUE_EXTEND) extend(items);
        else launch(consumer_of(static_cast<QueueId>(fullest)), items);
        device_.queue.enqueueFillBuffer(pool_.counters, 0u, fullest * sizeof(cl_uint), sizeof(cl_uint));
        counters = read_counters(WF_QUEUE_COUNT); // the statistics
    }
}

Stage WavefrontIntegrator::consumer_of(QueueId queue) {
    for (int s = 0; s < kStageKernels; ++s)
        if (kStageQueue[s] == queue) return static_cast<Stage>(s);
    throw std::logic_error("no stage consumes queue " + std::to_string(queue));
}

} // namespace wf
