/* sort_by_material — reorders the extension queue after intersect so that
 * shade meets the paths grouped by the material they hit (--sort-materials).
 * On a GPU this keeps the work-items of a group on one branch of the BSDF;
 * on a CPU it is a test of what the extra passes cost. A counting sort in
 * three launches:
 *   count_materials   a histogram of keys, per work-group in local memory;
 *   scan_materials    one work-item turns the counts into start offsets;
 *   scatter_materials each path to its key's range, one global atomic per
 *                     work-group and key, into `sorted`, which the host
 *                     copies back over the extension queue.
 * The key is the material index + 1 (0 for a miss), modulo WF_SORT_KEYS:
 * materials beyond it share keys, which still groups them. The image cannot
 * change: shade's work per path does not depend on its place in the queue. */
#include "path_state.h"

#define WF_SORT_KEYS 256

inline uint material_key(const PathState* path, uint slot, __global const Triangle* triangles) {
    const int triangle = as_int(path->hit[slot].w);
    return triangle < 0 ? 0u : (triangles[triangle].material + 1u) % WF_SORT_KEYS;
}

/* Zeroes the group's local key counts (every work-item calls it). */
inline void clear_keys(__local uint* keys) {
    for (uint k = get_local_id(0); k < WF_SORT_KEYS; k += get_local_size(0)) keys[k] = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
}

__kernel void count_materials(WF_STAGE_PARAMS, __global const Triangle* triangles, __global uint* key_counts) {
    WF_BIND_PATH_STATE(path);
    __local uint keys[WF_SORT_KEYS];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_EXTEND, &slot);
    clear_keys(keys);
    if (active) atomic_inc(&keys[material_key(&path, slot, triangles)]);
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint k = get_local_id(0); k < WF_SORT_KEYS; k += get_local_size(0))
        if (keys[k]) atomic_add(&key_counts[k], keys[k]);
}

__kernel void scan_materials(__global uint* key_counts) {
    if (get_global_id(0) != 0) return; /* launched as one work-group; one work-item scans */
    uint start = 0u;
    for (uint k = 0; k < WF_SORT_KEYS; ++k) {
        const uint count = key_counts[k];
        key_counts[k] = start;
        start += count;
    }
}

__kernel void scatter_materials(WF_STAGE_PARAMS, __global const Triangle* triangles, __global uint* key_starts,
                                __global uint* sorted) {
    WF_BIND_PATH_STATE(path);
    __local uint keys[WF_SORT_KEYS];
    __local uint group_start[WF_SORT_KEYS];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_EXTEND, &slot);
    const uint key = active ? material_key(&path, slot, triangles) : 0u;
    clear_keys(keys);
    const uint at = active ? atomic_inc(&keys[key]) : 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint k = get_local_id(0); k < WF_SORT_KEYS; k += get_local_size(0))
        if (keys[k]) group_start[k] = atomic_add(&key_starts[k], keys[k]);
    barrier(CLK_LOCAL_MEM_FENCE);
    if (active) sorted[group_start[key] + at] = slot;
}
