/* queue_push.h — appending path slots to a queue, and counting.
 *
 * WF_QUEUE_PUSH picks how (--queue-push; the image is the same either way):
 *   WF_PUSH_GROUP  (a GPU's default) one global atomic per work-group and
 *                  counter, after the group's shares are gathered by local
 *                  atomics;
 *   WF_PUSH_ATOMIC one global atomic per work-item (on PoCL about 100 plain
 *                  writes' worth each: the baseline the others are measured by);
 *   WF_PUSH_SCAN   a prefix sum over the work-group in local memory, then one
 *                  global atomic: order-preserving compaction;
 *   WF_PUSH_SERIAL (a CPU's default) the same sums, order-preserving too,
 *                  taken in turn by one work-item, then one global atomic:
 *                  a CPU runs a work-group on one thread, where each local
 *                  atomic is a locked instruction that waits for every store
 *                  before it (on the Cornell box's shadow rays, about a tenth
 *                  of intersect_shadow's time) and the sum a plain loop; a
 *                  GPU would leave the group's other work-items idle.
 * SCAN and SERIAL need WF_LOCAL_SIZE, the launch's local size.
 *
 * Contract: every work-item of the group calls these functions, in the same
 * order, outside any divergent branch (they hold barriers). `scratch` is
 * WF_QUEUE_SCRATCH __local uints declared once at kernel scope. They are
 * always inlined: left static functions with their barriers (a GPU's
 * program, WF_STATIC_FUNCTIONS), they crashed PoCL 3.1's compiler on the
 * megakernel (--kernels gpu --integrator megakernel on a CPU device). */
#ifndef WF_QUEUE_PUSH_H
#define WF_QUEUE_PUSH_H

#include "wavefront/compat.h"

#define WF_PUSH_GROUP 0
#define WF_PUSH_ATOMIC 1
#define WF_PUSH_SCAN 2
#define WF_PUSH_SERIAL 3
#ifndef WF_QUEUE_PUSH
#define WF_QUEUE_PUSH WF_PUSH_GROUP
#endif

#if WF_QUEUE_PUSH == WF_PUSH_SCAN || WF_QUEUE_PUSH == WF_PUSH_SERIAL
#define WF_QUEUE_SCRATCH (WF_LOCAL_SIZE + 1)
#else
#define WF_QUEUE_SCRATCH 2
#endif

/* Adds `amount` from each work-item to `*counter`; returns the value of the
 * counter where this work-item's share starts. */
WF_FORCE_INLINE uint group_atomic_add(volatile __global uint* counter, uint amount, __local uint* scratch) {
#if WF_QUEUE_PUSH == WF_PUSH_ATOMIC
    return amount ? atomic_add(counter, amount) : 0u;
#elif WF_QUEUE_PUSH == WF_PUSH_SCAN
    /* Hillis-Steele inclusive scan; scratch[WF_LOCAL_SIZE] carries the group's base. */
    const uint lid = get_local_id(0);
    scratch[lid] = amount;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint offset = 1; offset < WF_LOCAL_SIZE; offset <<= 1) {
        const uint before = lid >= offset ? scratch[lid - offset] : 0u;
        barrier(CLK_LOCAL_MEM_FENCE);
        scratch[lid] += before;
        barrier(CLK_LOCAL_MEM_FENCE);
    }
    const uint inclusive = scratch[lid];
    if (lid == WF_LOCAL_SIZE - 1) scratch[WF_LOCAL_SIZE] = inclusive ? atomic_add(counter, inclusive) : 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    return scratch[WF_LOCAL_SIZE] + inclusive - amount;
#elif WF_QUEUE_PUSH == WF_PUSH_SERIAL
    /* Exclusive sums in place; scratch[WF_LOCAL_SIZE] carries the group's base. */
    const uint lid = get_local_id(0);
    scratch[lid] = amount;
    barrier(CLK_LOCAL_MEM_FENCE);
    if (lid == 0) {
        uint sum = 0u;
        for (uint i = 0u; i < WF_LOCAL_SIZE; ++i) {
            const uint share = scratch[i];
            scratch[i] = sum;
            sum += share;
        }
        scratch[WF_LOCAL_SIZE] = sum ? atomic_add(counter, sum) : 0u;
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    return scratch[WF_LOCAL_SIZE] + scratch[lid];
#else
    if (get_local_id(0) == 0) scratch[0] = 0;
    barrier(CLK_LOCAL_MEM_FENCE);
    const uint offset_in_group = amount ? atomic_add(&scratch[0], amount) : 0;
    barrier(CLK_LOCAL_MEM_FENCE);
    if (get_local_id(0) == 0) scratch[1] = scratch[0] ? atomic_add(counter, scratch[0]) : 0;
    barrier(CLK_LOCAL_MEM_FENCE);
    return scratch[1] + offset_in_group;
#endif
}

/* Appends `slot` to queue `queue` when `push` holds. */
WF_FORCE_INLINE void queue_push(__global uint* queues, volatile __global uint* counters, uint pool_size,
                       uint queue, uint slot, bool push, __local uint* scratch) {
    const uint at = group_atomic_add(&counters[queue], push ? 1u : 0u, scratch);
    if (push) queues[queue * pool_size + at] = slot;
}

/* Appends each of slot[0 .. count) whose next[i] is `queue`: queue_push for
 * a work-item with several slots (geometry/trace_width.h). */
WF_FORCE_INLINE void queue_push_each(__global uint* queues, volatile __global uint* counters, uint pool_size, uint queue,
                               const uint* slot, const uint* next, uint count, __local uint* scratch) {
    uint pushed = 0u;
    for (uint i = 0; i < count; ++i) pushed += next[i] == queue ? 1u : 0u;
    uint at = group_atomic_add(&counters[queue], pushed, scratch);
    for (uint i = 0; i < count; ++i)
        if (next[i] == queue) queues[queue * pool_size + at++] = slot[i];
}

/* Adds 1 to counters[bucket] for each work-item with `count` set. `histogram`
 * is `buckets` __local uints declared once at kernel scope; the work-group must
 * have at least `buckets` work-items. */
WF_FORCE_INLINE void group_histogram_add(volatile __global uint* counters, uint buckets, uint bucket, bool count,
                                __local uint* histogram) {
    const uint lid = get_local_id(0);
    if (lid < buckets) histogram[lid] = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    if (count) atomic_inc(&histogram[bucket]);
    barrier(CLK_LOCAL_MEM_FENCE);
    if (lid < buckets && histogram[lid]) atomic_add(&counters[lid], histogram[lid]);
}

#endif
