/* megakernel.cl — the same path tracer as wavefront.cl, in one kernel: each
 * work-item takes its slot's next sample through the stage list
 * (wavefront/stage_graph.h) in turn, each stage's step (stages/stage_step.h)
 * taking the path from the queue that stage consumes and returning the queue
 * it goes to next, until accumulate has added it to its pixel. The functions
 * and their order along a path are the wavefront's, and the path state lives
 * in the same arrays, so the two integrators give the same bytes; what
 * differs is only how work is grouped into launches (Laine, Karras and Aila,
 * "Megakernels Considered Harmful", HPG 2013). A stage added to the list is
 * walked here once its header is included below. */
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
    const StageView view = {&path, &params, &camera, &scene, &film};
    StageTally tally = {0u, 0u, 0u, 0u};
    /* The wavefront's queues, one path at a time: each pass of the list
     * moves the path through every stage that takes it where it stands, in
     * the list's order, which is the order along a path; accumulate frees
     * the slot (REGENERATE), and a slot without a sample left starts none
     * (WF_QUEUE_COUNT). */
    uint queue = slot < params.pool_size ? WF_QUEUE_REGENERATE : WF_QUEUE_COUNT;
    while (queue != WF_QUEUE_COUNT) {
#define WF_MEGAKERNEL_STEP(stage, kernel, consumed) \
        if (queue == WF_QUEUE_##consumed) queue = kernel##_step(&view, slot, &tally);
        WF_STAGES(WF_MEGAKERNEL_STEP)
#undef WF_MEGAKERNEL_STEP
        if (queue == WF_QUEUE_REGENERATE) break; /* accumulated */
    }
    /* Counted once per work-group, outside the divergent loop (the adds hold barriers). */
    group_atomic_add(&counters[WF_COUNTER_CLOSEST_RAYS], tally.closest_rays, scratch);
    group_atomic_add(&counters[WF_COUNTER_SHADOW_RAYS], tally.shadow_rays, scratch);
    group_atomic_add(&counters[WF_COUNTER_NONFINITE], tally.nonfinite, scratch);
    group_atomic_add(&counters[WF_COUNTER_BUSY_SLOTS], tally.started != 0u ? 1u : 0u, scratch);
    group_histogram_add(&counters[WF_COUNTER_PATH_LENGTHS], WF_PATH_LENGTH_BUCKETS,
                        path_length_bucket(tally.started ? path_depth(&path, slot) : 0u), tally.started != 0u,
                        histogram);
}
