// megakernel_integrator.h — drives kernels/megakernel.cl: each launch takes one
// sample of every slot that has samples left through the whole path, so a
// round is spp × (pixels per slot) launches and there are no queues to read
// between stages. The comparison with the wavefront is Laine, Karras and
// Aila's ("Megakernels Considered Harmful", HPG 2013).
#pragma once

#include "integrator/path_integrator.h"

namespace wf {

class MegakernelIntegrator : public PathIntegrator {
public:
    MegakernelIntegrator(const OpenClDevice& device, const cl::Program& program, const DeviceScene& scene,
                         const Camera& camera, const RenderSettings& settings);

    void render_to(uint32_t round_spp) override;

private:
    cl::Kernel kernel_;
};

} // namespace wf
