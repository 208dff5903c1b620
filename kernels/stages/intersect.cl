/* intersect — the closest hit of every ray in the extension queue. */
#include "path_state.h"
#include "geometry/bvh_traverse.h"

inline void intersect_path(PathState* path, uint slot, __global const BvhNode* nodes,
                           __global const Triangle* triangles, const SceneTextures* textures) {
    const RayHit hit = bvh_closest_hit(nodes, triangles, path->ray_origin[slot].xyz, path->ray_direction[slot].xyz,
                                       INFINITY, textures);
    path->hit[slot] = (float4)(hit.t, hit.u, hit.v, as_float(hit.triangle));
}

__kernel void intersect(WF_STAGE_PARAMS, __global const BvhNode* nodes, __global const Triangle* triangles,
                        WF_SCENE_TEXTURE_PARAMS) {
    WF_BIND_PATH_STATE(path);
    WF_BIND_SCENE_TEXTURES(textures);
    uint slot;
    if (!queue_slot(params.pool_size, queues, counters, WF_QUEUE_EXTEND, &slot)) return;
    intersect_path(&path, slot, nodes, triangles, &textures);
}
