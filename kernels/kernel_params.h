/* kernel_params.h — the one parameter list every kernel of the render starts
 * with, and its binding into the structs stage functions take.
 *
 * WF_STAGE_PARAMS is, in order: one __global pointer per path-state field
 * (include/wavefront/path_state.h), per scene buffer (scene_buffers.h) and per
 * film buffer (film_buffers.h), then the render constants, the camera, the
 * queues, the counters and the pixel list (kernels/path_view.h). Every stage
 * kernel and the megakernel take the same list, so the host binds them all
 * with one loop over the same lists
 * (host/integrator/stage_args.cpp); a kernel's own arguments follow it.
 * WF_BIND_STAGE_ARGS gathers the pointers into `path`, `scene` and `film`. */
#ifndef WF_KERNEL_PARAMS_H
#define WF_KERNEL_PARAMS_H

#include "path_view.h"
#include "scene_view.h"
#include "film_view.h"
#include "wavefront/counters.h"

/* Parameters are prefixed so that a stage's locals (hit, pixel, ...) never
 * shadow them. */
#define WF_PATH_PARAM(type, name, what) __global type* path_##name,
#define WF_SCENE_PARAM(type, name, what) __global const type* scene_##name,
#define WF_FILM_PARAM(type, name, extent, what) __global type* film_##name,
#define WF_PATH_ARG(type, name, what) path_##name,
#define WF_SCENE_ARG(type, name, what) scene_##name,
#define WF_FILM_ARG(type, name, extent, what) film_##name,

#define WF_STAGE_PARAMS                                                                            \
    WF_PATH_STATE(WF_PATH_PARAM) WF_SCENE_BUFFERS(WF_SCENE_PARAM) WF_FILM_BUFFERS(WF_FILM_PARAM)   \
    const RenderParams params, const Camera camera, __global uint *queues, volatile __global uint *counters,  \
    __global const uint *pixel_list

#if WF_GPU_TRAVERSAL
/* A GPU's traversal stacks (geometry/bvh_traverse.h), in local memory, which
 * only a kernel's own scope may declare; kernels that trace nothing leave it
 * unused, and the compiler drops it. */
#define WF_BIND_TRAVERSAL_STACKS                                                                   \
    __local uint traversal_nodes[WF_TRAVERSAL_STACK_ENTRIES];                                      \
    __local uchar traversal_slots[WF_TRAVERSAL_STACK_ENTRIES];
#define WF_TRAVERSAL_STACK_ARGS traversal_nodes, traversal_slots
#else
#define WF_BIND_TRAVERSAL_STACKS
#define WF_TRAVERSAL_STACK_ARGS
#endif

#define WF_BIND_STAGE_ARGS                                                                         \
    WF_BIND_TRAVERSAL_STACKS                                                                       \
    PathState path = {WF_PATH_STATE(WF_PATH_ARG) pixel_list};                                                 \
    const Scene scene = {WF_SCENE_BUFFERS(WF_SCENE_ARG) WF_TRAVERSAL_STACK_ARGS};                  \
    const FilmBuffers film = {WF_FILM_BUFFERS(WF_FILM_ARG)}

#endif
