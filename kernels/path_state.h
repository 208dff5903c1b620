/* path_state.h — the kernels' view of the path state declared in
 * include/wavefront/path_state.h.
 *
 * Every stage kernel starts its parameter list with WF_STAGE_PARAMS: one
 * __global pointer per path-state field (in declaration order), then the render
 * constants, the queues and the counters. The host sets the same arguments in
 * the same order (host/integrator/path_pool.cpp). WF_BIND_PATH_STATE gathers the field
 * pointers into one PathState so stage functions take a single argument. */
#ifndef WF_KERNEL_PATH_STATE_H
#define WF_KERNEL_PATH_STATE_H

#include "wavefront/path_state.h"

#define WF_PATH_MEMBER(type, name, what) __global type* name;
/* Parameters are prefixed so that a stage's locals (hit, pixel, ...) never
 * shadow them. */
#define WF_PATH_PARAM(type, name, what) __global type* path_##name,
#define WF_PATH_NAME(type, name, what) path_##name,

typedef struct PathState {
    WF_PATH_STATE(WF_PATH_MEMBER)
} PathState;

#define WF_STAGE_PARAMS                                                                      \
    WF_PATH_STATE(WF_PATH_PARAM)                                                            \
    const RenderParams params, __global uint *queues, volatile __global uint *counters

#define WF_BIND_PATH_STATE(var) PathState var = {WF_PATH_STATE(WF_PATH_NAME)}

/* What the w lanes hold (include/wavefront/path_state.h). */
inline uint path_depth(const PathState* path, uint slot) { return as_uint(path->throughput[slot].w); }
inline uint path_samples_started(const PathState* path, uint slot) { return as_uint(path->radiance[slot].w); }

/* Slot i owns pixels i, i + pool, i + 2·pool, ... and takes them in turn, a
 * sample of each: its n-th sample (from 0) is sample n / owned of pixel
 * i + (n % owned)·pool. */
typedef struct PathSample {
    uint pixel;
    uint sample; /* its index within the pixel */
} PathSample;

inline uint pixels_owned(const RenderParams* params, uint slot) {
    return (params->pixel_count - 1u - slot) / params->pool_size + 1u;
}

inline PathSample nth_sample(const RenderParams* params, uint slot, uint n) {
    const uint owned = pixels_owned(params, slot);
    PathSample s;
    s.pixel = slot + (n % owned) * params->pool_size;
    s.sample = n / owned;
    return s;
}

/* The sample the slot's path is tracing. */
inline PathSample current_sample(const PathState* path, const RenderParams* params, uint slot) {
    return nth_sample(params, slot, path_samples_started(path, slot) - 1u);
}

/* Whether this work-item has a path in `queue` (the queue is shorter than
 * the launch, which is rounded up to whole work-groups), and which slot. */
inline bool queue_slot(uint pool_size, __global const uint* queues, volatile __global const uint* counters,
                       uint queue, uint* slot) {
    const uint index = get_global_id(0);
    const bool active = index < counters[queue];
    *slot = active ? queues[queue * pool_size + index] : 0u;
    return active;
}

#endif
