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
 * The key is the material index + 1 (0 for a miss), modulo WF_SORT_KEYS
 * (wavefront/stage_graph.h):
 * materials beyond it share keys, which still groups them. The image cannot
 * change: shade's work per path does not depend on its place in the queue. */
#ifndef WF_STAGE_SORT_BY_MATERIAL_H
#define WF_STAGE_SORT_BY_MATERIAL_H

#include "wavefront/compat.h"
#include "wavefront/stage_graph.h"
#include "path_view.h"
#include "scene_view.h"
#include "geometry/triangle_blocks.h"

WF_INLINE uint material_key(const PathState* path, uint slot, const Scene* scene) {
    const int triangle = path_hit_triangle(path, slot);
    return triangle < 0 ? 0u : (triangle_material(scene->triangles, (uint)triangle) + 1u) % WF_SORT_KEYS;
}

/* Zeroes the group's local key counts (every work-item calls it). */
WF_INLINE void clear_keys(__local uint* keys) {
    for (uint k = get_local_id(0); k < WF_SORT_KEYS; k += get_local_size(0)) keys[k] = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
}

/* Adds the group's keys to the global histogram (every work-item calls it). */
WF_INLINE void count_keys(__local uint* keys, bool active, uint key, __global uint* key_counts) {
    clear_keys(keys);
    if (active) atomic_inc(&keys[key]);
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint k = get_local_id(0); k < WF_SORT_KEYS; k += get_local_size(0))
        if (keys[k]) atomic_add(&key_counts[k], keys[k]);
}

/* Key counts to start offsets, in place; one work-item. */
WF_INLINE void scan_keys(__global uint* key_counts) {
    uint start = 0u;
    for (uint k = 0; k < WF_SORT_KEYS; ++k) {
        const uint count = key_counts[k];
        key_counts[k] = start;
        start += count;
    }
}

/* Writes the slot into its key's range of `sorted` (every work-item calls it). */
WF_INLINE void scatter_by_key(__local uint* keys, __local uint* group_start, bool active, uint key, uint slot,
                           __global uint* key_starts, __global uint* sorted) {
    clear_keys(keys);
    const uint at = active ? atomic_inc(&keys[key]) : 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint k = get_local_id(0); k < WF_SORT_KEYS; k += get_local_size(0))
        if (keys[k]) group_start[k] = atomic_add(&key_starts[k], keys[k]);
    barrier(CLK_LOCAL_MEM_FENCE);
    if (active) sorted[group_start[key] + at] = slot;
}

#endif
