/* path_view.h — the kernels' view of the path state declared in
 * include/wavefront/path_state.h: the PathState that gathers one slot array
 * per field (bound by kernel_params.h), the only code that reads or writes
 * the integer lanes packed into its float4s, and which pixel and sample a
 * slot is tracing. */
#ifndef WF_KERNEL_PATH_STATE_H
#define WF_KERNEL_PATH_STATE_H

#include "wavefront/compat.h"
#include "wavefront/path_state.h"
#include "compiled_features.h"
#include "wavefront/render_params.h"
#include "wavefront/stage_graph.h"
#include "geometry/trace_width.h"

#define WF_PATH_MEMBER(type, name, what) __global type* name;
typedef struct PathState {
    WF_PATH_STATE(WF_PATH_MEMBER)
    __global const uint* pixel_list; /* the pixels traced, where RenderParams.pixel_list says so */
} PathState;
#undef WF_PATH_MEMBER

/* The packed lanes (include/wavefront/path_state.h says what each holds). */
WF_INLINE uint path_depth(const PathState* path, uint slot) { return as_uint(path->throughput[slot].w); }
WF_INLINE void set_path_throughput(PathState* path, uint slot, float3 throughput, uint depth) {
    path->throughput[slot] = (float4)(throughput, as_float(depth));
}
WF_INLINE uint path_samples_started(const PathState* path, uint slot) { return as_uint(path->radiance[slot].w); }
/* A new sample: no radiance yet, and one more sample started. */
WF_INLINE void start_path_radiance(PathState* path, uint slot, uint samples_started) {
    path->radiance[slot] = (float4)(0.0f, 0.0f, 0.0f, as_float(samples_started));
}
WF_INLINE int path_hit_triangle(const PathState* path, uint slot) { return as_int(path->hit[slot].w); }
/* The continuation ray, and the number roulette will draw for it. */
WF_INLINE void set_path_ray(PathState* path, uint slot, float3 origin, float3 direction, float pdf, float roulette_u) {
    path->ray_origin[slot] = (float4)(origin, roulette_u);
    path->ray_direction[slot] = (float4)(direction, pdf);
}
WF_INLINE float path_roulette_number(const PathState* path, uint slot) { return path->ray_origin[slot].w; }
WF_INLINE void set_path_hit(PathState* path, uint slot, float t, float u, float v, int triangle) {
    path->hit[slot] = (float4)(t, u, v, as_float(triangle));
}
#if WF_HAS_INSTANCES
/* The closest hit's placement (a two-level tree's) rides in the shadow
 * segment's w, free between the shadow ray and the next one: intersect
 * writes it after the path's last shadow ray is traced (a path waits in one
 * queue at a time), shade reads it before it sets the next. */
WF_INLINE void set_path_hit_instance(PathState* path, uint slot, int instance) {
    path->shadow_segment[slot].w = as_float(instance);
}
WF_INLINE int path_hit_instance(const PathState* path, uint slot) { return as_int(path->shadow_segment[slot].w); }
#endif
/* The light a pending shadow ray delivers if nothing blocks it, the bounce
 * layer it joins, and whether the path goes on after it. */
WF_INLINE void set_shadow_light(PathState* path, uint slot, float3 radiance, uint layer, bool then_continue) {
    path->shadow_radiance[slot] = (float4)(radiance, as_float(layer | (then_continue ? WF_SHADOW_THEN_CONTINUE : 0u)));
}
WF_INLINE uint shadow_light_layer(float4 shadow_radiance) { return as_uint(shadow_radiance.w) & ~WF_SHADOW_THEN_CONTINUE; }
WF_INLINE bool shadow_then_continues(float4 shadow_radiance) {
    return (as_uint(shadow_radiance.w) & WF_SHADOW_THEN_CONTINUE) != 0u;
}

/* Of the traced pixels, from `first`, slot i owns first + i, first + i + pool,
 * first + i + 2·pool, ... and takes them in turn, a sample of each: its n-th
 * sample (from 0) is sample n / owned of pixel first + i + (n % owned)·pool,
 * or of the pixel that entry of the pixel list names (adaptive sampling's
 * unfinished pixels, host/render/adaptive_sampling.h). */
typedef struct PathSample {
    uint pixel;
    uint sample; /* its index within the pixel */
} PathSample;

WF_INLINE uint pixels_owned(const RenderParams* params, uint slot) {
    return (params->traced_pixels - 1u - slot) / params->pool_size + 1u;
}

WF_INLINE PathSample nth_sample(const PathState* path, const RenderParams* params, uint slot, uint n) {
    const uint owned = pixels_owned(params, slot);
    const uint traced = params->first_pixel + slot + (n % owned) * params->pool_size;
    PathSample s;
    s.pixel = params->pixel_list ? path->pixel_list[traced] : traced;
    s.sample = n / owned;
    return s;
}

/* The sample the slot's path is tracing. */
WF_INLINE PathSample current_sample(const PathState* path, const RenderParams* params, uint slot) {
    return nth_sample(path, params, slot, path_samples_started(path, slot) - 1u);
}

/* Whether this work-item has a path in `queue` (the queue is shorter than
 * the launch, which is rounded up to whole work-groups), and which slot. */
WF_INLINE bool queue_slot(uint pool_size, __global const uint* queues, volatile __global const uint* counters,
                       uint queue, uint* slot) {
    const uint index = get_global_id(0);
    const bool active = index < counters[queue];
    *slot = active ? queues[queue * pool_size + index] : 0u;
    return active;
}

/* The slots a work-item of a ray-tracing stage takes from `queue`, into
 * slot[], and how many: `per_item` consecutive entries of its work-group's
 * share of the queue (WF_TRACE_WIDTH, or intersect's WF_TRACE_SLOTS:
 * geometry/trace_width.h), so that the group's first 1 / per_item of
 * work-items take them all and the rest none. */
WF_INLINE uint queue_slots_to_trace(uint pool_size, __global const uint* queues, volatile __global const uint* counters,
                                    uint queue, uint per_item, uint* slot) {
    const uint group_size = get_local_size(0), first = per_item * get_local_id(0);
    const uint index = get_group_id(0) * group_size + first, length = counters[queue];
    if (first >= group_size || index >= length) return 0u;
    const uint count = min(min(per_item, group_size - first), length - index);
    for (uint i = 0; i < count; ++i) slot[i] = queues[queue * pool_size + index + i];
    return count;
}

#endif
