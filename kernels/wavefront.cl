/* wavefront.cl — the program of the wavefront integrator: one thin kernel
 * per stage, built together once.
 *
 *   generate → intersect → shade → intersect_shadow → roulette → accumulate
 *
 * Each kernel takes the one parameter list of kernel_params.h, finds its path
 * slot in the queue it consumes (include/wavefront/path_state.h), calls its
 * stage function (stages/), and appends the slot to the queue that comes
 * next. The stage functions are the megakernel's too (megakernel.cl);
 * host/integrator/wavefront_scheduler.cpp launches these. */
#include "kernel_params.h"
#include "common/queue_push.h"
#include "stages/generate.h"
#include "stages/intersect.h"
#include "stages/sort_by_material.h"
#include "stages/shade.h"
#include "stages/intersect_shadow.h"
#include "stages/roulette.h"
#include "stages/accumulate.h"

__kernel void generate(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local uint scratch[WF_QUEUE_SCRATCH];
    uint slot;
    const bool started = queue_slot(params.pool_size, queues, counters, WF_QUEUE_REGENERATE, &slot) &&
                         start_camera_sample(&path, &params, &camera, slot);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_EXTEND, slot, started, scratch);
}

__kernel void intersect(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    uint slot;
    if (!queue_slot(params.pool_size, queues, counters, WF_QUEUE_EXTEND, &slot)) return;
    intersect_path(&path, slot, &scene);
}

/* --sort-materials, between intersect and shade (stages/sort_by_material.h). */
__kernel void count_materials(WF_STAGE_PARAMS, __global uint* key_counts) {
    WF_BIND_STAGE_ARGS;
    __local uint keys[WF_SORT_KEYS];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_EXTEND, &slot);
    count_keys(keys, active, active ? material_key(&path, slot, &scene) : 0u, key_counts);
}

__kernel void scan_materials(__global uint* key_counts) {
    if (get_global_id(0) == 0) scan_keys(key_counts); /* launched as one work-group */
}

__kernel void scatter_materials(WF_STAGE_PARAMS, __global uint* key_starts, __global uint* sorted) {
    WF_BIND_STAGE_ARGS;
    __local uint keys[WF_SORT_KEYS];
    __local uint group_start[WF_SORT_KEYS];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_EXTEND, &slot);
    scatter_by_key(keys, group_start, active, active ? material_key(&path, slot, &scene) : 0u, slot, key_starts,
                   sorted);
}

__kernel void shade(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local uint scratch[WF_QUEUE_SCRATCH];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_EXTEND, &slot);
    const uint outcome = active ? shade_path(&path, &params, slot, &scene, &film) : WF_SHADE_FINISHED;
    /* Each path goes to exactly one queue: one with a shadow ray waits for it
     * (intersect_shadow sends it on), so no stage can overwrite the pending
     * ray whatever order the scheduler launches them in. */
    const bool shadow_ray = (outcome & WF_SHADE_SHADOW_RAY) != 0u;
    const bool continues = (outcome & WF_SHADE_CONTINUES) != 0u;
    group_atomic_add(&counters[WF_COUNTER_CLOSEST_RAYS], active ? 1u : 0u, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_SHADOW, slot, shadow_ray, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_CONTINUE, slot, !shadow_ray && continues, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_FINISHED, slot, active && !shadow_ray && !continues,
               scratch);
}

__kernel void intersect_shadow(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local uint scratch[WF_QUEUE_SCRATCH];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_SHADOW, &slot);
    const bool continues = active && trace_shadow_ray(&path, &params, slot, &scene, &film);
    group_atomic_add(&counters[WF_COUNTER_SHADOW_RAYS], active ? 1u : 0u, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_CONTINUE, slot, continues, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_FINISHED, slot, active && !continues, scratch);
}

__kernel void roulette(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local uint scratch[WF_QUEUE_SCRATCH];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_CONTINUE, &slot);
    const bool survives = active && survives_roulette(&path, &params, slot);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_EXTEND, slot, survives, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_FINISHED, slot, active && !survives, scratch);
}

__kernel void accumulate(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local uint scratch[WF_QUEUE_SCRATCH];
    __local uint histogram[WF_PATH_LENGTH_BUCKETS];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_FINISHED, &slot);
    const bool nonfinite = active && accumulate_path(&path, &params, slot, &film);
    group_atomic_add(&counters[WF_COUNTER_NONFINITE], nonfinite ? 1u : 0u, scratch);
    const uint bucket = path_length_bucket(active ? path_depth(&path, slot) : 0u);
    group_histogram_add(&counters[WF_COUNTER_PATH_LENGTHS], WF_PATH_LENGTH_BUCKETS, bucket, active, histogram);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_REGENERATE, slot, active, scratch);
}
