/* megakernel.cl — the same path tracer as wavefront.cl, in one kernel: each
 * work-item takes its slot's next sample through the stage functions in turn
 * (start_camera_sample, intersect_path, shade_path, trace_shadow_ray,
 * roulette_path, accumulate_path), each returning the queue of the stage that
 * comes next (wavefront/stage_graph.h), until the path is finished, then adds
 * it to its pixel. The functions and their order along a path are the wavefront's, and
 * the path state lives in the same arrays, so the two integrators give the
 * same bytes; what differs is only how work is grouped into launches (Laine,
 * Karras and Aila, "Megakernels Considered Harmful", HPG 2013). */
#include "kernel_params.h"
#include "common/queue_push.h"
#include "stages/generate.h"
#include "stages/intersect.h"
#include "stages/shade.h"
#include "stages/intersect_shadow.h"
#include "stages/roulette.h"
#include "stages/accumulate.h"

/* One launch traces one sample for every slot that has samples left. */
__kernel void megakernel(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local uint scratch[WF_QUEUE_SCRATCH];
    __local uint histogram[WF_PATH_LENGTH_BUCKETS];
    const uint slot = get_global_id(0);
    const bool started = slot < params.pool_size && start_camera_sample(&path, &params, &camera, slot);
    uint closest_rays = 0u, shadow_rays = 0u;
    bool nonfinite = false;
    if (started) {
        /* The wavefront's queues, one path at a time: where it goes next. */
        for (uint queue = WF_QUEUE_EXTEND; queue != WF_QUEUE_FINISHED;) {
            switch (queue) {
            case WF_QUEUE_EXTEND:
                intersect_path(&path, slot, &scene);
                ++closest_rays;
                queue = shade_path(&path, &params, slot, &scene, &film);
                break;
            case WF_QUEUE_SHADOW:
                ++shadow_rays;
                queue = trace_shadow_ray(&path, &params, slot, &scene, &film);
                break;
            default: /* WF_QUEUE_CONTINUE */
                queue = roulette_path(&path, &params, slot);
                break;
            }
        }
        nonfinite = accumulate_path(&path, &params, slot, &film);
    }
    /* Counted once per work-group, outside the divergent loop (the adds hold barriers). */
    group_atomic_add(&counters[WF_COUNTER_CLOSEST_RAYS], closest_rays, scratch);
    group_atomic_add(&counters[WF_COUNTER_SHADOW_RAYS], shadow_rays, scratch);
    group_atomic_add(&counters[WF_COUNTER_NONFINITE], nonfinite ? 1u : 0u, scratch);
    group_histogram_add(&counters[WF_COUNTER_PATH_LENGTHS], WF_PATH_LENGTH_BUCKETS,
                        path_length_bucket(started ? path_depth(&path, slot) : 0u), started, histogram);
}
