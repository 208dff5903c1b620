/* intersect_shadow — any hit along the slot's pending shadow segment; an
 * unoccluded one delivers its light sample's radiance to the path, which then
 * goes on to roulette or to accumulation, as shade decided. */
#ifndef WF_STAGE_INTERSECT_SHADOW_H
#define WF_STAGE_INTERSECT_SHADOW_H

#include "wavefront/compat.h"
#include "wavefront/stage_graph.h"
#include "path_view.h"
#include "scene_view.h"
#include "film_view.h"
#include "geometry/bvh_traverse.h"
#include "common/bounce_layers.h"

/* Traces the slot's shadow segment and adds its light if nothing blocks it;
 * returns the queue the path goes to next. */
WF_INLINE uint trace_shadow_ray(PathState* path, const RenderParams* params, uint slot, const Scene* scene,
                             const FilmBuffers* film) {
    const float4 light = path->shadow_radiance[slot];
    const bool occluded = bvh_any_hit(scene->nodes, scene->triangles, path->shadow_origin[slot].xyz,
                                      path->shadow_segment[slot].xyz, 1.0f, scene);
    if (!occluded) {
        path->radiance[slot].xyz += light.xyz;
        add_to_bounce_layer(params, film, current_sample(path, params, slot).pixel, shadow_light_layer(light),
                            light.xyz);
    }
    return shadow_then_continues(light) ? WF_QUEUE_CONTINUE : WF_QUEUE_FINISHED;
}

#endif
