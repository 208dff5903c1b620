// megakernel_integrator.cpp — one launch per sample of every slot.
#include "integrator/megakernel_integrator.h"

#include <chrono>

namespace wf {

MegakernelIntegrator::MegakernelIntegrator(const OpenClDevice& device, const cl::Program& program,
                                          const DeviceScene& scene, const Camera& camera,
                                          const RenderSettings& settings)
    : PathIntegrator(device, scene, camera, settings), kernel_(program, "megakernel") {}

void MegakernelIntegrator::render_to(uint32_t round_spp) {
    const auto start = std::chrono::steady_clock::now();
    params_.spp = round_spp;
    set_stage_args(kernel_, stage_args());
    run_whole_paths(STAGE_MEGAKERNEL, kernel_);
    device_.queue.finish();
    stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace wf
