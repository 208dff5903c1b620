/* intersect_shadow — any hit along each pending shadow segment; an unoccluded
 * one delivers its light sample's radiance to the path, which then goes on to
 * roulette or to accumulation, as shade decided. */
#include "path_state.h"
#include "geometry/bvh_traverse.h"
#include "common/queue_push.h"
#include "common/bounce_layers.h"

/* Traces the slot's shadow segment and adds its light if nothing blocks it;
 * returns whether the path continues after it. */
inline bool trace_shadow_ray(PathState* path, const RenderParams* params, uint slot, __global const BvhNode* nodes,
                             __global const Triangle* triangles, const SceneTextures* textures,
                             __global float4* layers, __global float4* layer_compensation) {
    const float4 light = path->shadow_radiance[slot]; /* w: bounce layer and WF_SHADOW_THEN_CONTINUE, as bits */
    const uint flags = as_uint(light.w);
    const bool occluded = bvh_any_hit(nodes, triangles, path->shadow_origin[slot].xyz,
                                      path->shadow_segment[slot].xyz, 1.0f, textures);
    if (!occluded) {
        path->radiance[slot].xyz += light.xyz;
        add_to_bounce_layer(params, layers, layer_compensation, current_sample(path, params, slot).pixel,
                            flags & ~WF_SHADOW_THEN_CONTINUE, light.xyz);
    }
    return (flags & WF_SHADOW_THEN_CONTINUE) != 0u;
}

__kernel void intersect_shadow(WF_STAGE_PARAMS, __global const BvhNode* nodes,
                               __global const Triangle* triangles, WF_SCENE_TEXTURE_PARAMS,
                               __global float4* layers, __global float4* layer_compensation) {
    WF_BIND_PATH_STATE(path);
    WF_BIND_SCENE_TEXTURES(textures);
    __local uint scratch[WF_QUEUE_SCRATCH];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_SHADOW, &slot);
    const bool continues =
        active && trace_shadow_ray(&path, &params, slot, nodes, triangles, &textures, layers, layer_compensation);
    group_atomic_add(&counters[WF_COUNTER_SHADOW_RAYS], active ? 1u : 0u, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_CONTINUE, slot, continues, scratch);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_FINISHED, slot, active && !continues, scratch);
}
