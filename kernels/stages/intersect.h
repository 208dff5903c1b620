/* intersect — the closest hit of the slot's ray, stored in its path state. */
#ifndef WF_STAGE_INTERSECT_H
#define WF_STAGE_INTERSECT_H

#include "wavefront/compat.h"
#include "path_view.h"
#include "scene_view.h"
#include "geometry/bvh_traverse.h"

WF_INLINE void intersect_path(PathState* path, uint slot, const Scene* scene) {
    const RayHit hit = bvh_closest_hit(scene->nodes, scene->triangles, path->ray_origin[slot].xyz,
                                       path->ray_direction[slot].xyz, INFINITY, scene);
    set_path_hit(path, slot, hit.t, hit.u, hit.v, hit.triangle);
}

#endif
