/* accumulate — adds each finished path's radiance to its pixel and frees its slot.
 *
 * A pixel's samples all come from the one slot that owns it (generate.cl), so
 * each pixel has one writer and receives its samples in sample order: no
 * atomics, and the same sums whatever the pool size. Sums are compensated
 * (Neumaier), so a million samples per pixel lose no precision to the float
 * accumulator. A sample with a NaN or Inf component is counted and dropped. */
#include "path_state.h"
#include "common/finite.h"
#include "common/queue_push.h"

/* sum + compensation carries the running total to twice float precision. */
inline void compensated_add(__global float4* sum, __global float4* compensation, float4 x) {
    const float4 s = *sum;
    const float4 t = s + x;
    const int4 sum_larger = isgreaterequal(fabs(s), fabs(x));
    *compensation += select((x - t) + s, (s - t) + x, sum_larger);
    *sum = t;
}

__kernel void accumulate(WF_STAGE_PARAMS, __global float4* film_sum,
                         __global float4* film_compensation, __global uint* film_samples) {
    WF_BIND_PATH_STATE(path);
    __local uint scratch[2];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_FINISHED, &slot);
    bool nonfinite = false;
    if (active) {
        const uint pixel = path.pixel[slot];
        const float3 radiance = path.radiance[slot].xyz;
        nonfinite = !is_finite3(radiance);
        compensated_add(&film_sum[pixel], &film_compensation[pixel],
                        nonfinite ? (float4)(0.0f) : (float4)(radiance, 0.0f));
        film_samples[pixel] += 1u;
    }
    group_atomic_add(&counters[WF_COUNTER_NONFINITE], nonfinite ? 1u : 0u, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_REGENERATE, slot, active, scratch);
}
