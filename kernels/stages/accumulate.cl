/* accumulate — adds each finished path's radiance to its pixel and frees its slot.
 *
 * A pixel's samples all come from the one slot that owns it (generate.cl), so
 * each pixel has one writer and receives its samples in sample order: no
 * atomics, and the same sums whatever the pool size. Beside the sum, the sum of
 * squares gives each pixel's sample variance, from which the host estimates
 * the error of the image without a reference. Both sums are compensated. A
 * sample with a NaN or Inf component is counted and dropped, and every path is
 * counted by its bounce count (the path-length histogram of the report). */
#include "path_state.h"
#include "common/finite.h"
#include "common/film_add.h"
#include "common/queue_push.h"

/* Adds the slot's finished sample to its pixel; returns whether it was
 * dropped as non-finite. */
inline bool accumulate_path(PathState* path, const RenderParams* params, uint slot, __global float4* film_sum,
                            __global float4* film_compensation, __global float4* film_sum_squares,
                            __global float4* film_squares_compensation, __global uint* film_samples) {
    const uint pixel = current_sample(path, params, slot).pixel;
    const float3 radiance = path->radiance[slot].xyz;
    const bool nonfinite = !is_finite3(radiance);
    const float4 x = nonfinite ? (float4)(0.0f) : (float4)(radiance, 0.0f);
    film_add(film_sum, film_compensation, pixel, x);
    film_add(film_sum_squares, film_squares_compensation, pixel, x * x);
    film_samples[pixel] += 1u;
    return nonfinite;
}

/* The path-length histogram's bucket for a path of `bounces` bounces. */
inline uint path_length_bucket(uint bounces) {
    return bounces == 0u ? 0u : min(32u - clz(bounces), (uint)WF_PATH_LENGTH_BUCKETS - 1u);
}

__kernel void accumulate(WF_STAGE_PARAMS, __global float4* film_sum, __global float4* film_compensation,
                         __global float4* film_sum_squares, __global float4* film_squares_compensation,
                         __global uint* film_samples) {
    WF_BIND_PATH_STATE(path);
    __local uint scratch[WF_QUEUE_SCRATCH];
    __local uint histogram[WF_PATH_LENGTH_BUCKETS];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_FINISHED, &slot);
    const bool nonfinite = active && accumulate_path(&path, &params, slot, film_sum, film_compensation, film_sum_squares,
                                                     film_squares_compensation, film_samples);
    group_atomic_add(&counters[WF_COUNTER_NONFINITE], nonfinite ? 1u : 0u, scratch);
    const uint bucket = path_length_bucket(active ? path_depth(&path, slot) : 0u);
    group_histogram_add(&counters[WF_COUNTER_PATH_LENGTHS], WF_PATH_LENGTH_BUCKETS, bucket, active, histogram);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_REGENERATE, slot, active, scratch);
}
