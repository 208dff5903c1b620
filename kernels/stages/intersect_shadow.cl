/* intersect_shadow — any hit along each pending shadow segment; an unoccluded
 * one delivers its light sample's radiance to the path. */
#include "path_state.h"
#include "geometry/bvh_traverse.h"
#include "common/queue_push.h"
#include "common/bounce_layers.h"

__kernel void intersect_shadow(WF_STAGE_PARAMS, __global const BvhNode* nodes,
                               __global const Triangle* triangles, WF_SCENE_TEXTURE_PARAMS,
                               __global float4* layers, __global float4* layer_compensation) {
    WF_BIND_PATH_STATE(path);
    WF_BIND_SCENE_TEXTURES(textures);
    __local uint scratch[2];
    uint slot;
    const bool active = queue_slot(params.pool_size, queues, counters, WF_QUEUE_SHADOW, &slot);
    if (active) {
        const bool occluded = bvh_any_hit(nodes, triangles, path.shadow_origin[slot].xyz,
                                          path.shadow_segment[slot].xyz, 1.0f, &textures);
        if (!occluded) {
            const float4 light = path.shadow_radiance[slot]; /* w: its bounce layer, as bits */
            path.radiance[slot].xyz += light.xyz;
            add_to_bounce_layer(&params, layers, layer_compensation, path.pixel[slot], as_uint(light.w), light.xyz);
        }
    }
    group_atomic_add(&counters[WF_COUNTER_SHADOW_RAYS], active ? 1u : 0u, scratch);
}
