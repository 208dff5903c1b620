// stage_args.h — binds the parameter list every kernel of a render starts
// with (WF_STAGE_PARAMS, kernels/kernel_params.h): the path state, the scene
// buffers and the film buffers, each by the list that declares it
// (include/wavefront/{path_state,scene_buffers,film_buffers}.h), then the
// render constants, the camera, the queues and the counters. Both
// integrators, the ray batches and the tests bind through it.
#pragma once

#include <CL/opencl.hpp>

#include "device/device_scene.h"
#include "film/film.h"
#include "integrator/path_pool.h"
#include "wavefront/render_params.h"

namespace wf {

struct StageArgs {
    const PathPool& pool;
    const RenderParams& params;
    const Camera& camera;
    const DeviceScene& scene;
    const Film& film;
};

// Sets the shared arguments; returns the index of the kernel's own first one.
cl_uint set_stage_args(cl::Kernel& kernel, const StageArgs& args);

// Sets consecutive arguments of `kernel` from index `first` on; returns the next index.
template <class... Args> cl_uint set_kernel_args(cl::Kernel& kernel, cl_uint first, const Args&... args) {
    (kernel.setArg(first++, args), ...);
    return first;
}

} // namespace wf
