/* wavefront.cl — the program of the wavefront integrator: one thin kernel
 * per stage, built together once.
 *
 *   generate → intersect → shade → intersect_shadow → roulette → accumulate
 *
 * Each kernel takes the one parameter list of kernel_params.h, finds its path
 * slot in the queue it consumes (the stage list of wavefront/stage_graph.h),
 * calls its stage function (stages/), and appends the slot to the queue that
 * function returns. The stage functions are the megakernel's too
 * (megakernel.cl); host/integrator/wavefront_integrator.cpp launches these.
 * group_wavefront, last, runs the same stages inside each work-group, over
 * local queues indexed by the same queue ids. */
#include "kernel_params.h"
#include "common/queue_push.h"
#include "stages/generate.h"
#include "stages/intersect.h"
#include "stages/sort_by_material.h"
#include "stages/shade.h"
#include "stages/shade_lanes.h"
#if WF_SHADE_IN_TWO
#include "stages/shade_two_kernels.h"
#endif
#include "stages/generate_lanes.h"
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
    uint slot[WF_TRACE_SLOTS];
    const uint count =
        queue_slots_to_trace(params.pool_size, queues, counters, WF_QUEUE_EXTEND, WF_TRACE_SLOTS, slot);
    if (count > 0u) intersect_paths(&path, slot, count, &scene);
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

/* Each kernel pushes its paths to the queues its stage function returns, every
 * work-item to each of the stage's next queues in turn (the pushes hold
 * barriers). Shade may run as two kernels over the extension queue
 * (WF_SHADE_IN_TWO, by default a GPU's program on the global-queue
 * schedules; stages/shade_two_kernels.h): surface leaves each path's record,
 * shade takes it on. */
#if WF_SHADE_IN_TWO
__kernel void surface(WF_STAGE_PARAMS, __global float4* shade_records) {
    WF_BIND_STAGE_ARGS;
    uint slot;
    if (queue_slot(params.pool_size, queues, counters, WF_QUEUE_EXTEND, &slot))
        shade_surface_path(&path, &params, slot, &scene, &film, shade_records);
}
#define WF_SHADE_PARAMS WF_STAGE_PARAMS, __global float4* shade_records
#define WF_SHADE_ONE_PATH shade_bsdf_path(&path, &params, slot, &scene, shade_records)
#else
#define WF_SHADE_PARAMS WF_STAGE_PARAMS
#define WF_SHADE_ONE_PATH shade_path(&path, &params, slot, &scene, &film)
#endif

__kernel void shade(WF_SHADE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local uint scratch[WF_QUEUE_SCRATCH];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_EXTEND, &slot);
    const uint next = active ? WF_SHADE_ONE_PATH : WF_QUEUE_COUNT;
    group_atomic_add(&counters[WF_COUNTER_CLOSEST_RAYS], active ? 1u : 0u, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_SHADOW, slot, next == WF_QUEUE_SHADOW, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_CONTINUE, slot, next == WF_QUEUE_CONTINUE, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_FINISHED, slot, next == WF_QUEUE_FINISHED, scratch);
}

__kernel void intersect_shadow(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local uint scratch[WF_QUEUE_SCRATCH];
    uint slot[WF_TRACE_WIDTH], next[WF_TRACE_WIDTH];
    const uint count =
        queue_slots_to_trace(params.pool_size, queues, counters, WF_QUEUE_SHADOW, WF_TRACE_WIDTH, slot);
    if (count > 0u) trace_shadow_rays(&path, &params, slot, count, &scene, &film, next);
    group_atomic_add(&counters[WF_COUNTER_SHADOW_RAYS], count, scratch);
    queue_push_each(queues, counters, params.pool_size, WF_QUEUE_CONTINUE, slot, next, count, scratch);
    queue_push_each(queues, counters, params.pool_size, WF_QUEUE_FINISHED, slot, next, count, scratch);
}

__kernel void roulette(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local uint scratch[WF_QUEUE_SCRATCH];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_CONTINUE, &slot);
    const uint next = active ? roulette_path(&path, &params, slot) : WF_QUEUE_COUNT;
    queue_push(queues, counters, params.pool_size, WF_QUEUE_EXTEND, slot, next == WF_QUEUE_EXTEND, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_FINISHED, slot, next == WF_QUEUE_FINISHED, scratch);
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

/* --schedule group: the same stage functions, each work-group running them
 * over its own WF_LOCAL_SIZE slots, stage by stage, with its queues in local
 * memory. Each stage runs over the group's paths before the next starts
 * (PoCL runs the code between two barriers as a loop over the work-items), so
 * a stage's code and the group's path state stay in the core's caches instead
 * of the whole pool streaming through memory at every stage. A slot whose path
 * ends starts its next sample in the same launch, up to WF_GROUP_SAMPLES a
 * launch, so that the group's stages run over a full queue instead of
 * dwindling to the longest path's few last bounces. A slot's pixels and
 * samples are the other schedules', and so are the bytes. Pushes are local
 * atomics: a work-group runs on one thread. Compiled for that schedule alone
 * (WF_GROUP_SCHEDULE, render/device_renderer.cpp). */
#if WF_GROUP_SCHEDULE
/* Samples a slot may start in one launch: enough that the tail of a launch,
 * where the group's last paths run on alone, is a small part of it; few
 * enough that the host reads the counters (progress, Ctrl-C) often. */
#ifndef WF_GROUP_SAMPLES
#define WF_GROUP_SAMPLES 4u
#endif

typedef struct LocalQueue {
    uint slots[WF_LOCAL_SIZE];
    uint length;
} LocalQueue;

WF_INLINE void local_push(__local LocalQueue* q, uint slot) { q->slots[atomic_inc(&q->length)] = slot; }

/* The slots work-item `lid` traces from a local queue, WF_TRACE_WIDTH of them
 * (geometry/trace_width.h), as queue_slots_to_trace takes them from a global
 * one; returns how many (none for the group's later work-items). */
WF_INLINE uint local_slots_to_trace(__local const LocalQueue* q, uint lid, uint* slot) {
    const uint first = WF_TRACE_WIDTH * lid;
    if (first >= q->length) return 0u;
    const uint count = min((uint)WF_TRACE_WIDTH, q->length - first);
    for (uint i = 0u; i < count; ++i) slot[i] = q->slots[first + i];
    return count;
}

/* The extension queue's slots work-item `lid` traces, WF_TRACE_SLOTS of
 * them: the queue's camera rays, from `cameras` on, in runs of their own,
 * so that a run of them is a packet (stages/intersect.h). *camera says
 * whether the run is of camera rays. */
WF_INLINE uint extension_slots_to_trace(__local const LocalQueue* q, uint cameras, uint lid, uint* slot, bool* camera) {
    const uint before = (cameras + WF_TRACE_SLOTS - 1u) / WF_TRACE_SLOTS; /* work-items for those before */
    const uint first = lid < before ? WF_TRACE_SLOTS * lid : cameras + WF_TRACE_SLOTS * (lid - before);
    const uint end = lid < before ? cameras : q->length;
    *camera = lid >= before;
    if (first >= end) return 0u;
    const uint count = min((uint)WF_TRACE_SLOTS, end - first);
    for (uint i = 0u; i < count; ++i) slot[i] = q->slots[first + i];
    return count;
}

/* A slot's next sample, begun where the last one ended. With lanes on a CPU,
 * its camera ray waits for the extension queue's next intersect region, which
 * writes a run of them at once (stages/generate_lanes.h) before tracing them. */
WF_INLINE bool group_start_sample(PathState* path, const RenderParams* params, const Camera* camera, uint slot) {
#if WF_CAMERA_RAYS_IN_LANES
    return begin_camera_sample(path, params, slot);
#else
    return start_camera_sample(path, params, camera, slot);
#endif
}

__kernel void group_wavefront(WF_STAGE_PARAMS) {
    WF_BIND_STAGE_ARGS;
    __local LocalQueue queue[WF_QUEUE_COUNT]; /* the global queues' local twins, by QueueId */
    __local uint scratch[WF_QUEUE_SCRATCH];
    __local uint histogram[WF_PATH_LENGTH_BUCKETS];
#ifdef WF_GROUP_LANES
    __local float lanes[WF_LANE_FIELDS * WF_LANE_CAPACITY];
    __local uint lanes_length;
#endif
    __local uint samples_started[WF_LOCAL_SIZE]; /* in this launch, by slot - first_slot */
    /* The extension queue's camera rays start here: the samples started
     * in the last pass wait in the group's (else unused) regenerate queue
     * until it ends, and then join the queue's tail together. */
    __local uint cameras;
    const uint lid = get_local_id(0), first_slot = get_group_id(0) * get_local_size(0);
    samples_started[lid] = 0u;
    if (lid < WF_QUEUE_COUNT) queue[lid].length = 0u;
    if (lid == 0) cameras = 0u;
    if (lid < WF_PATH_LENGTH_BUCKETS) histogram[lid] = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    const uint own = get_global_id(0);
    if (own < params.pool_size && group_start_sample(&path, &params, &camera, own)) {
        samples_started[lid] = 1u;
        local_push(&queue[WF_QUEUE_EXTEND], own);
    }
    /* by the entries this work-item took: */
    uint closest_rays = 0u, shadow_rays = 0u, nonfinite = 0u, lane_paths = 0u, lane_slots = 0u;
    /* Work-item 0 counts the paths that entered each queue, for the study of
     * the schedule; added to the global queues' counters, which this
     * schedule leaves unused, at the end (CounterSnapshot says so); those
     * that entered generate, the camera samples started, from samples_started. */
    uint entered[WF_QUEUE_COUNT];
    for (uint q = 0u; q < WF_QUEUE_COUNT; ++q) entered[q] = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint extending; (extending = queue[WF_QUEUE_EXTEND].length) > 0u;) {
        {
            uint slot[WF_TRACE_SLOTS];
            bool camera_rays;
            const uint count = extension_slots_to_trace(&queue[WF_QUEUE_EXTEND], cameras, lid, slot, &camera_rays);
#if WF_CAMERA_RAYS_IN_LANES
            if (count > 0u && camera_rays) write_camera_rays(&path, &params, &camera, slot, count);
#endif
            if (count > 0u) intersect_paths(&path, slot, count, &scene);
            for (uint i = 0u; i < count; ++i) prefetch_surface(&scene, path_hit_triangle(&path, slot[i]));
        }
#ifdef WF_GROUP_LANES
        if (lid == 0) lanes_length = 0u;
#endif
        barrier(CLK_LOCAL_MEM_FENCE);
#ifdef WF_GROUP_LANES
        /* Shade in three steps: each path's arrival and surface, after
         * which a path that goes on waits in local memory (with its light
         * sample, unless the lanes take it); those waiting, WF_LANE_WIDTH paths a work-item
         * (stages/shade_lanes.h); their emission and scatters into the path
         * state. Where the lanes find the surface too (WF_SURFACE_IN_LANES),
         * every hit waits after its arrival alone. */
        uint next = WF_QUEUE_FINISHED;
        uint lane_at = WF_LANE_CAPACITY; /* none */
        if (lid < extending) {
            const uint slot = queue[WF_QUEUE_EXTEND].slots[lid];
            Arrival arrival;
#if WF_SURFACE_IN_LANES
            if (path_arrival(&path, &params, slot, &scene, &film, &arrival)) {
                lane_at = atomic_inc(&lanes_length);
                shade_lanes_put_arrival(lanes, lane_at, &arrival);
            }
#else
            if (path_arrival(&path, &params, slot, &scene, &film, &arrival)) {
                /* The light's numbers now, for shade_light; the lanes draw
                 * the BSDF's (shade_lanes_numbers). */
                arrival_light_numbers(&params, &arrival);
                arrival.u = (float4)(0.0f);
                ShadeContext shading;
                if (shade_surface(&path, &params, slot, &scene, &film, &arrival, &shading)) {
                    if (!WF_LIGHTS_IN_LANES) shade_light(&params, &scene, &shading);
                    lane_at = atomic_inc(&lanes_length);
                    shade_lanes_put(lanes, lane_at, &shading, &arrival);
                }
            }
#endif
        }
        barrier(CLK_LOCAL_MEM_FENCE);
        if (lid * WF_LANE_WIDTH < lanes_length) {
            shade_lanes_run(lanes, lid * WF_LANE_WIDTH, lanes_length, &params, &scene);
            lane_paths += min((uint)WF_LANE_WIDTH, lanes_length - lid * WF_LANE_WIDTH);
            lane_slots += WF_LANE_WIDTH;
        }
        barrier(CLK_LOCAL_MEM_FENCE);
#endif
        if (lid < extending) {
            const uint slot = queue[WF_QUEUE_EXTEND].slots[lid];
#ifdef WF_GROUP_LANES
            if (lane_at < WF_LANE_CAPACITY && shade_lanes_emission(lanes, lane_at, &path, &params, &film, slot)) {
                float roulette_u;
                ShadowRay_x1 shadow_ray;
                const Scatter_x1 scattered = shade_lanes_get(lanes, lane_at, &roulette_u, &shadow_ray);
                if (scattered.shadow) write_shadow_ray(&path, slot, &shadow_ray);
                next = write_scatter(&path, slot, &scattered, roulette_u);
            }
#else
            const uint next = shade_path(&path, &params, slot, &scene, &film);
#endif
            ++closest_rays;
            local_push(&queue[next], slot);
        }
        barrier(CLK_LOCAL_MEM_FENCE);
        /* The extension queue is consumed: roulette refills it. */
        if (lid == 0) {
            entered[WF_QUEUE_EXTEND] += extending;
            queue[WF_QUEUE_EXTEND].length = 0u;
        }
        {
            uint slot[WF_TRACE_WIDTH], next[WF_TRACE_WIDTH];
            const uint count = local_slots_to_trace(&queue[WF_QUEUE_SHADOW], lid, slot);
            if (count > 0u) trace_shadow_rays(&path, &params, slot, count, &scene, &film, next);
            shadow_rays += count;
            for (uint i = 0u; i < count; ++i) local_push(&queue[next[i]], slot[i]);
        }
        barrier(CLK_LOCAL_MEM_FENCE);
        if (lid < queue[WF_QUEUE_CONTINUE].length) {
            const uint slot = queue[WF_QUEUE_CONTINUE].slots[lid];
            local_push(&queue[roulette_path(&path, &params, slot)], slot);
        }
        barrier(CLK_LOCAL_MEM_FENCE);
        if (lid < queue[WF_QUEUE_FINISHED].length) {
            const uint slot = queue[WF_QUEUE_FINISHED].slots[lid];
            nonfinite += accumulate_path(&path, &params, slot, &film) ? 1u : 0u;
            atomic_inc(&histogram[path_length_bucket(path_depth(&path, slot))]);
            /* The slot's next sample, while it has one this launch. */
            if (samples_started[slot - first_slot] < WF_GROUP_SAMPLES &&
                group_start_sample(&path, &params, &camera, slot)) {
                ++samples_started[slot - first_slot];
                local_push(&queue[WF_QUEUE_REGENERATE], slot);
            }
        }
        barrier(CLK_LOCAL_MEM_FENCE);
        if (lid == 0) {
            entered[WF_QUEUE_SHADOW] += queue[WF_QUEUE_SHADOW].length;
            entered[WF_QUEUE_CONTINUE] += queue[WF_QUEUE_CONTINUE].length;
            entered[WF_QUEUE_FINISHED] += queue[WF_QUEUE_FINISHED].length;
            queue[WF_QUEUE_SHADOW].length = queue[WF_QUEUE_CONTINUE].length = queue[WF_QUEUE_FINISHED].length = 0u;
            cameras = queue[WF_QUEUE_EXTEND].length;
            for (uint i = 0u; i < queue[WF_QUEUE_REGENERATE].length; ++i)
                queue[WF_QUEUE_EXTEND].slots[cameras + i] = queue[WF_QUEUE_REGENERATE].slots[i];
            queue[WF_QUEUE_EXTEND].length += queue[WF_QUEUE_REGENERATE].length;
            queue[WF_QUEUE_REGENERATE].length = 0u;
        }
        barrier(CLK_LOCAL_MEM_FENCE);
    }
    group_atomic_add(&counters[WF_COUNTER_CLOSEST_RAYS], closest_rays, scratch);
    group_atomic_add(&counters[WF_COUNTER_SHADOW_RAYS], shadow_rays, scratch);
    group_atomic_add(&counters[WF_COUNTER_NONFINITE], nonfinite, scratch);
    group_atomic_add(&counters[WF_COUNTER_LANE_PATHS], lane_paths, scratch);
    group_atomic_add(&counters[WF_COUNTER_LANE_SLOTS], lane_slots, scratch);
    group_atomic_add(&counters[WF_COUNTER_BUSY_SLOTS], samples_started[lid] != 0u ? 1u : 0u, scratch);
    if (lid < WF_PATH_LENGTH_BUCKETS && histogram[lid])
        atomic_add(&counters[WF_COUNTER_PATH_LENGTHS + lid], histogram[lid]);
    group_atomic_add(&counters[WF_QUEUE_REGENERATE], samples_started[lid], scratch);
    if (lid == 0)
        for (uint q = 0u; q < WF_QUEUE_COUNT; ++q)
            if (entered[q]) atomic_add(&counters[q], entered[q]);
}
#endif
