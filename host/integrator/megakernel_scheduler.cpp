// megakernel_scheduler.cpp — one launch per sample of every slot.
#include "integrator/megakernel_scheduler.h"

#include <chrono>
#include <stdexcept>

namespace wf {

MegakernelScheduler::MegakernelScheduler(const OpenClDevice& device, const cl::Program& program,
                                         const DeviceScene& scene, const Camera& camera,
                                         const RenderSettings& settings)
    : PathIntegrator(device, scene, camera, settings), kernel_(program, "megakernel") {}

void MegakernelScheduler::render_to(uint32_t spp) {
    const auto start = std::chrono::steady_clock::now();
    params_.spp = spp;
    set_stage_args(kernel_, stage_args());
    device_.queue.enqueueFillBuffer(pool_.counters, 0u, 0, WF_COUNTER_COUNT * sizeof(cl_uint));
    // Each launch finishes every sample it starts, so the samples done are
    // those restored from a stopped render and those this render traced.
    const uint64_t wanted = uint64_t{params_.pixel_count} * spp;
    while (restored_samples_ + stats_.samples < wanted && !stopping()) {
        launch(STAGE_MEGAKERNEL, kernel_, pool_.size());
        const uint64_t before = stats_.samples;
        read_counters(WF_QUEUE_COUNT);
        if (stats_.samples == before) throw std::logic_error("megakernel: a launch traced no sample");
    }
    device_.queue.finish();
    stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace wf
