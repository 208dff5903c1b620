// stage_args.cpp — the order here is WF_STAGE_PARAMS's, list by list.
#include "integrator/stage_args.h"

namespace wf {

cl_uint set_stage_args(cl::Kernel& kernel, const StageArgs& a) {
    cl_uint index = 0;
    for (const cl::Buffer& field : a.pool.fields()) kernel.setArg(index++, field);
#define WF_SET_SCENE_ARG(type, name, what) kernel.setArg(index++, a.scene.name);
    WF_SCENE_BUFFERS(WF_SET_SCENE_ARG)
#undef WF_SET_SCENE_ARG
#define WF_SET_FILM_ARG(type, name, extent, what) kernel.setArg(index++, a.film.name);
    WF_FILM_BUFFERS(WF_SET_FILM_ARG)
#undef WF_SET_FILM_ARG
    return set_kernel_args(kernel, index, a.params, a.camera, a.pool.queues, a.pool.counters, a.pool.pixel_list);
}

} // namespace wf
