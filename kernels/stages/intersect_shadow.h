/* intersect_shadow — any hit along each slot's pending shadow segment; an
 * unoccluded one delivers its light sample's radiance to the path, which then
 * goes on to roulette or to accumulation, as shade decided. A work-item
 * traces WF_TRACE_WIDTH slots at once (geometry/trace_width.h). */
#ifndef WF_STAGE_INTERSECT_SHADOW_H
#define WF_STAGE_INTERSECT_SHADOW_H

#include "wavefront/compat.h"
#include "wavefront/stage_graph.h"
#include "path_view.h"
#include "scene_view.h"
#include "film_view.h"
#include "geometry/bvh_traverse.h"
#include "common/bounce_layers.h"
#include "stages/stage_step.h"

/* Traces the shadow segments of slot[0 .. count), count from 1 to
 * WF_TRACE_WIDTH, and adds the light of each that nothing blocks; next[i]
 * is the queue slot[i] goes to next. */
WF_GPU_INLINE void trace_shadow_rays(PathState* path, const RenderParams* params, const uint* slot, uint count,
                                 const Scene* scene, const FilmBuffers* film, uint* next) {
    float3 origin[WF_TRACE_WIDTH], segment[WF_TRACE_WIDTH];
    RayHit hit[WF_TRACE_WIDTH];
    for (uint i = 0; i < count; ++i) {
        origin[i] = path->shadow_origin[slot[i]].xyz;
        segment[i] = path->shadow_segment[slot[i]].xyz;
    }
    bvh_traverse_rays(scene->nodes, scene->triangles, origin, segment, count, 1.0f, 1, scene, hit);
    for (uint i = 0; i < count; ++i) {
        const float4 light = path->shadow_radiance[slot[i]];
        if (hit[i].triangle < 0) { /* unoccluded */
            path->radiance[slot[i]].xyz += light.xyz;
            add_to_bounce_layer(params, film, current_sample(path, params, slot[i]).pixel, shadow_light_layer(light),
                                light.xyz);
        }
        next[i] = shadow_then_continues(light) ? WF_QUEUE_CONTINUE : WF_QUEUE_FINISHED;
    }
}

/* The same for one slot; returns the queue it goes to next. */
WF_INLINE uint trace_shadow_ray(PathState* path, const RenderParams* params, uint slot, const Scene* scene,
                                const FilmBuffers* film) {
    uint next;
    trace_shadow_rays(path, params, &slot, 1u, scene, film, &next);
    return next;
}

WF_FORCE_INLINE uint intersect_shadow_step(const StageView* v, uint slot, StageTally* t) {
    ++t->shadow_rays;
    return trace_shadow_ray(v->path, v->params, slot, v->scene, v->film);
}

#endif
