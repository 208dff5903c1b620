/* bvh_traverse.h — closest-hit and any-hit queries of a ray against the BVH
 * built by host/bvh_builder.h, shared by the kernels and the host.
 *
 * Promises: bvh_closest_hit returns what testing every triangle with
 * intersect_triangle (geometry/triangle_intersect.h) would: the hit of least t
 * in (0, t_max), equal t going to the lower triangle index, so the answer does
 * not depend on the order in which nodes are visited. bvh_any_hit is 1 exactly
 * when that search would find a hit. Either way the direction need not be unit
 * (a shadow ray may be the whole segment with t_max = 1), but it must be finite
 * with a largest component above 2^-100.
 *
 * The box test must never cull a node holding a triangle that the triangle
 * test hits. Three things could make it do so, and each is answered:
 *  - Its own rounding: the far distance is scaled by 1 + 2^-21 >= 1 + 2 gamma_3
 *    (Ize, "Robust BVH Ray Traversal", JCGT 2013; pbrt-v4).
 *  - The triangle test's rounding, which acts like moving each vertex by up to
 *    4 ulps of its distance from the origin (Woop et al. 2013, section 5), and
 *    moves t by as much. Every box is grown by four times that:
 *    pad = 2^-20 (16 ulps) x (the root box's reach from the origin + |origin|).
 *    It costs nothing per node: the origin used against lower planes moves up
 *    by pad, the one used against upper planes down.
 *  - A direction component of 0: a moved origin on a plane of that axis
 *    would give 0 * infinity = NaN, and OpenCL leaves min and max of NaN
 *    undefined. The reciprocal is clamped to +-FLT_MAX instead, which keeps
 *    the arithmetic free of NaN; since the growth keeps a ray inside a slab at
 *    least pad from its planes, it leaves the slab only at pad * FLT_MAX,
 *    beyond every hit.
 *
 * Nodes are visited front to back with a stack of WF_BVH_STACK_SIZE indices;
 * the builder keeps every tree shallower than that. */
#ifndef WF_BVH_TRAVERSE_H
#define WF_BVH_TRAVERSE_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"
#include "geometry/triangle_intersect.h"

#define WF_BVH_STACK_SIZE 64

WF_DEVICE_BEGIN

typedef struct RayHit {
    float t;
    float u; /* barycentrics as in TriangleHit */
    float v;
    int32_t triangle; /* -1 on a miss, else an index into the BVH-ordered triangles */
} RayHit;

/* A ray prepared for slab tests against boxes grown as described above. */
typedef struct BoxRay {
    float3 origin_lo; /* the origin for distances to lower planes */
    float3 origin_hi; /* the origin for distances to upper planes */
    float3 inv_direction;
} BoxRay;

WF_INLINE BoxRay box_ray(WF_GLOBAL const BvhNode* root, float3 origin, float3 direction) {
    const float3 reach = max(fabs(load_float3(root->lo) - origin), fabs(load_float3(root->hi) - origin));
    /* The |origin| term keeps origin +- pad some ulps away from origin, so the
     * growth survives rounding however far the scene is from the world origin. */
    const float3 offset = fabs(origin);
    const float pad = 0x1p-20f * (reach.x + reach.y + reach.z + offset.x + offset.y + offset.z);
    const float flt_max = 0x1.fffffep127f;
    BoxRay ray;
    ray.origin_lo = origin + pad;
    ray.origin_hi = origin - pad;
    ray.inv_direction = max(min(1.0f / direction, make_float3(flt_max, flt_max, flt_max)),
                            make_float3(-flt_max, -flt_max, -flt_max));
    return ray;
}

/* Where the ray enters the node's box when it meets it before t_limit, else -1. */
WF_INLINE float box_entry(const BoxRay* ray, WF_GLOBAL const BvhNode* node, float t_limit) {
    const float3 t_lo = (load_float3(node->lo) - ray->origin_lo) * ray->inv_direction;
    const float3 t_hi = (load_float3(node->hi) - ray->origin_hi) * ray->inv_direction;
    const float3 t_near = min(t_lo, t_hi);
    const float3 t_far = max(t_lo, t_hi);
    const float entry = max(max(t_near.x, t_near.y), max(t_near.z, 0.0f));
    const float exit = min(min(t_far.x, t_far.y), min(t_far.z, t_limit)) * (1.0f + 0x1p-21f);
    return entry <= exit ? entry : -1.0f;
}

/* The closest hit in (0, t_max), or the first one found when stop_at_first_hit
 * is set. A popped node is not tested again: it was culled against the closest
 * hit when pushed, and a closer hit since then still culls its children. */
WF_INLINE RayHit bvh_traverse(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const Triangle* triangles,
                              float3 origin, float3 direction, float t_max, int stop_at_first_hit) {
    const WatertightRay ray = watertight_ray(origin, direction);
    const BoxRay box = box_ray(nodes, origin, direction);
    RayHit hit;
    hit.t = t_max;
    hit.u = 0.0f;
    hit.v = 0.0f;
    hit.triangle = -1;
    if (box_entry(&box, nodes, t_max) < 0.0f) return hit;

    uint32_t stack[WF_BVH_STACK_SIZE];
    int stack_size = 0;
    uint32_t node = 0;
    for (;;) {
        const uint32_t first = nodes[node].first;
        const uint32_t count = nodes[node].count;
        if (count == 0) {
            const float entry_a = box_entry(&box, nodes + first, hit.t);
            const float entry_b = box_entry(&box, nodes + first + 1, hit.t);
            if (entry_a >= 0.0f && entry_b >= 0.0f) {
                /* The nearer child first: a hit there may cull the other. */
                const uint32_t nearer = entry_a <= entry_b ? first : first + 1;
                stack[stack_size++] = nearer == first ? first + 1 : first;
                node = nearer;
                continue;
            }
            if (entry_a >= 0.0f || entry_b >= 0.0f) {
                node = entry_a >= 0.0f ? first : first + 1;
                continue;
            }
        } else {
            for (uint32_t i = first; i < first + count; ++i) {
                TriangleHit candidate;
                if (!intersect_triangle(&ray, load_float3(triangles[i].v0), load_float3(triangles[i].v1),
                                        load_float3(triangles[i].v2), t_max, &candidate))
                    continue;
                /* At equal t the lower index wins, as in a search in index order. */
                if (candidate.t < hit.t || (candidate.t == hit.t && (int32_t)i < hit.triangle)) {
                    hit.t = candidate.t;
                    hit.u = candidate.u;
                    hit.v = candidate.v;
                    hit.triangle = (int32_t)i;
                    if (stop_at_first_hit) return hit;
                }
            }
        }
        if (stack_size == 0) return hit;
        node = stack[--stack_size];
    }
}

WF_INLINE RayHit bvh_closest_hit(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const Triangle* triangles,
                                 float3 origin, float3 direction, float t_max) {
    return bvh_traverse(nodes, triangles, origin, direction, t_max, 0);
}

/* 1 if any triangle is hit with t in (0, t_max). */
WF_INLINE int bvh_any_hit(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const Triangle* triangles, float3 origin,
                          float3 direction, float t_max) {
    return bvh_traverse(nodes, triangles, origin, direction, t_max, 1).triangle >= 0;
}

WF_DEVICE_END

#endif /* WF_BVH_TRAVERSE_H */
