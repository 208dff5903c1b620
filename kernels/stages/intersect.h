/* intersect — the closest hit of each slot's ray, stored in its path state;
 * a work-item traces WF_TRACE_WIDTH slots at once (geometry/trace_width.h). */
#ifndef WF_STAGE_INTERSECT_H
#define WF_STAGE_INTERSECT_H

#include "wavefront/compat.h"
#include "path_view.h"
#include "scene_view.h"
#include "geometry/bvh_traverse.h"

/* The closest hits of slot[0 .. count), count from 1 to WF_TRACE_WIDTH. */
WF_INLINE void intersect_paths(PathState* path, const uint* slot, uint count, const Scene* scene) {
    float3 origin[WF_TRACE_WIDTH], direction[WF_TRACE_WIDTH];
    RayHit hit[WF_TRACE_WIDTH];
    for (uint i = 0; i < count; ++i) {
        origin[i] = path->ray_origin[slot[i]].xyz;
        direction[i] = path->ray_direction[slot[i]].xyz;
    }
    bvh_traverse_rays(scene->nodes, scene->triangles, origin, direction, count, INFINITY, 0, scene, hit);
    for (uint i = 0; i < count; ++i) set_path_hit(path, slot[i], hit[i].t, hit[i].u, hit[i].v, hit[i].triangle);
}

WF_INLINE void intersect_path(PathState* path, uint slot, const Scene* scene) { intersect_paths(path, &slot, 1u, scene); }

#endif
