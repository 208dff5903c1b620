/* intersect — the closest hit of each slot's ray, stored in its path state;
 * a work-item takes WF_TRACE_SLOTS slots (geometry/trace_width.h): on a CPU,
 * rays from one point as a packet (geometry/bvh_packet.h), the others
 * WF_TRACE_WIDTH at once. */
#ifndef WF_STAGE_INTERSECT_H
#define WF_STAGE_INTERSECT_H

#include "wavefront/compat.h"
#include "path_view.h"
#include "scene_view.h"
#include "geometry/bvh_traverse.h"
#include "geometry/bvh_packet.h"
#include "stages/stage_step.h"

/* The closest hits of slot[0 .. count), count from 1 to WF_TRACE_SLOTS. */
WF_INLINE void intersect_paths(PathState* path, const uint* slot, uint count, const Scene* scene) {
    float3 origin[WF_TRACE_SLOTS], direction[WF_TRACE_SLOTS];
    RayHit hit[WF_TRACE_SLOTS];
    for (uint i = 0; i < count; ++i) {
        origin[i] = path->ray_origin[slot[i]].xyz;
        direction[i] = path->ray_direction[slot[i]].xyz;
    }
#ifdef WF_PACKET_RAYS
    Packet packet;
    if (count >= WF_PACKET_MIN_RAYS && packet_start(&packet, scene->nodes, origin, direction, count))
        bvh_closest_hits_packet(scene->nodes, scene->triangles, &packet, count, INFINITY, scene, hit);
    else
#endif
        /* Bounded by the constant, so that where the two are equal (a GPU)
         * the one pass indexes the arrays by constants, which keeps them in
         * registers. */
        for (uint i = 0; i < WF_TRACE_SLOTS && i < count; i += WF_TRACE_WIDTH)
            bvh_traverse_rays(scene->nodes, scene->triangles, origin + i, direction + i,
                              min((uint)WF_TRACE_WIDTH, count - i), INFINITY, 0, scene, hit + i);
    for (uint i = 0; i < count; ++i) {
        set_path_hit(path, slot[i], hit[i].t, hit[i].u, hit[i].v, hit[i].triangle);
#if WF_HAS_INSTANCES
        set_path_hit_instance(path, slot[i], hit[i].instance);
#endif
    }
}

WF_INLINE void intersect_path(PathState* path, uint slot, const Scene* scene) { intersect_paths(path, &slot, 1u, scene); }

/* The closest hit, for shade, which takes the extension queue next. */
WF_FORCE_INLINE uint intersect_step(const StageView* v, uint slot, StageTally* t) {
    intersect_path(v->path, slot, v->scene);
    ++t->closest_rays;
    return WF_QUEUE_EXTEND;
}

#endif
