/* queue_push.h — appending path slots to a queue, and counting, with one
 * global atomic per work-group and counter, not per item (on PoCL a per-item
 * global atomic costs about 100 plain writes).
 *
 * Contract: every work-item of the group calls these functions, in the same
 * order, outside any divergent branch (they hold barriers). `scratch` is two
 * __local uints declared once at kernel scope. */
#ifndef WF_QUEUE_PUSH_H
#define WF_QUEUE_PUSH_H

/* Adds `amount` from each work-item to `*counter`; returns the value of the
 * counter where this work-item's share starts. */
inline uint group_atomic_add(volatile __global uint* counter, uint amount, __local uint* scratch) {
    if (get_local_id(0) == 0) scratch[0] = 0;
    barrier(CLK_LOCAL_MEM_FENCE);
    const uint offset_in_group = amount ? atomic_add(&scratch[0], amount) : 0;
    barrier(CLK_LOCAL_MEM_FENCE);
    if (get_local_id(0) == 0) scratch[1] = scratch[0] ? atomic_add(counter, scratch[0]) : 0;
    barrier(CLK_LOCAL_MEM_FENCE);
    return scratch[1] + offset_in_group;
}

/* Appends `slot` to queue `queue` when `push` holds. */
inline void queue_push(__global uint* queues, volatile __global uint* counters, uint pool_size,
                       uint queue, uint slot, bool push, __local uint* scratch) {
    const uint at = group_atomic_add(&counters[queue], push ? 1u : 0u, scratch);
    if (push) queues[queue * pool_size + at] = slot;
}

/* Adds 1 to counters[bucket] for each work-item with `count` set. `histogram`
 * is `buckets` __local uints declared once at kernel scope; the work-group must
 * have at least `buckets` work-items. */
inline void group_histogram_add(volatile __global uint* counters, uint buckets, uint bucket, bool count,
                                __local uint* histogram) {
    const uint lid = get_local_id(0);
    if (lid < buckets) histogram[lid] = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    if (count) atomic_inc(&histogram[bucket]);
    barrier(CLK_LOCAL_MEM_FENCE);
    if (lid < buckets && histogram[lid]) atomic_add(&counters[lid], histogram[lid]);
}

#endif
