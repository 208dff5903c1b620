/* bvh_traverse.h — closest-hit and any-hit queries of a ray against the BVH
 * built by host/bvh_builder.h, shared by the kernels and the host.
 *
 * Promises: bvh_closest_hit returns what testing every triangle with
 * intersect_triangle (geometry/triangle_intersect.h) and passing each hit to
 * select_hit would return, in any order: the answer does not depend on the
 * order in which nodes are visited. bvh_any_hit is 1 exactly when that search
 * would find a hit. Either way the direction need not be unit (a shadow ray
 * may be the whole segment with t_max = 1), but it must be finite with a
 * largest component above 2^-100.
 *
 * Which hit is returned (select_hit): the closest, at equal t the lower
 * triangle index, except where rounding cannot tell an emitter from a surface
 * in front of it. A hit's exact t lies within t_error of its t, so the t of
 * two hits on one plane differ by at most the sum of their bounds. The window
 * of doubt ends at the least t + 2 t_error over all hits, and the closest
 * emitter hit (Triangle.light >= 0) inside it wins over the closest hit. So a
 * light exactly coplanar with the surface it is set in is found wherever its
 * bound is no larger than the surface's, and in practice everywhere, since the
 * bounds are conservative several times over (tests/test_coplanar.cpp checks
 * every pixel); the two no longer take turns from pixel to pixel as their
 * roundings fall. The emitter wins, not the surface, because next-event
 * estimation reaches it (its shadow segment stops short of that plane), and
 * MIS weighs each light sample against the chance that BRDF sampling hits
 * the same light: that direction must find the light, or light is lost.
 * Every part of the rule is a least value or a comparison with one, so it is
 * the same in any order, and the window's end can cull boxes: no node beyond
 * it can change the answer.
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
 * the builder keeps every tree shallower than that.
 *
 * On the device every query takes a HitFilter (materials/alpha_mask.h): a hit
 * it rejects (a transparent texel of an alpha-masked material) is as if the
 * triangle were not there. The host's queries, for the tests, have none. */
#ifndef WF_BVH_TRAVERSE_H
#define WF_BVH_TRAVERSE_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"
#include "geometry/triangle_intersect.h"

#ifdef __OPENCL_C_VERSION__
#include "materials/alpha_mask.h"
#define WF_HIT_FILTER_PARAM , const HitFilter* filter
#define WF_HIT_FILTER_ARG , filter
#define WF_HIT_PASSES(triangles, i, hit) hit_passes_filter(filter, triangles, i, (hit)->u, (hit)->v)
#else
#define WF_HIT_FILTER_PARAM
#define WF_HIT_FILTER_ARG
#define WF_HIT_PASSES(triangles, i, hit) 1
#endif

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

/* The hits met so far, as the rule above needs them. */
typedef struct HitSelection {
    RayHit closest;
    RayHit emitter;   /* the closest emitter hit */
    float window_end; /* least t + 2 t_error; t_max while there is none */
} HitSelection;

WF_INLINE HitSelection no_hits(float t_max) {
    HitSelection s;
    s.closest.t = t_max;
    s.closest.u = 0.0f;
    s.closest.v = 0.0f;
    s.closest.triangle = -1;
    s.emitter = s.closest;
    s.window_end = t_max;
    return s;
}

/* Whether a hit at t on triangle `index` comes before `than` (none yet: -1 at
 * t_max, which every hit is below): least t, then lower index. */
WF_INLINE int comes_before(float t, int32_t index, const RayHit* than) {
    return t < than->t || (t == than->t && index < than->triangle);
}

WF_INLINE void select_hit(HitSelection* s, const TriangleHit* hit, int32_t index, int emitter) {
    RayHit h;
    h.t = hit->t;
    h.u = hit->u;
    h.v = hit->v;
    h.triangle = index;
    if (comes_before(h.t, index, &s->closest)) s->closest = h;
    if (emitter && comes_before(h.t, index, &s->emitter)) s->emitter = h;
    s->window_end = min(s->window_end, hit->t + 2.0f * hit->t_error);
}

WF_INLINE RayHit selected_hit(const HitSelection* s) {
    return s->emitter.triangle >= 0 && s->emitter.t <= s->window_end ? s->emitter : s->closest;
}

/* The selected hit in (0, t_max), or the first one found when
 * stop_at_first_hit is set. A popped node is not tested again: it was culled
 * against the window's end when pushed, and an earlier end since then still
 * culls its children. */
WF_INLINE RayHit bvh_traverse(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const Triangle* triangles,
                              float3 origin, float3 direction, float t_max,
                              int stop_at_first_hit WF_HIT_FILTER_PARAM) {
    const WatertightRay ray = watertight_ray(origin, direction);
    const BoxRay box = box_ray(nodes, origin, direction);
    HitSelection selection = no_hits(t_max);
    if (box_entry(&box, nodes, t_max) < 0.0f) return selected_hit(&selection);

    uint32_t stack[WF_BVH_STACK_SIZE];
    int stack_size = 0;
    uint32_t node = 0;
    for (;;) {
        const uint32_t first = nodes[node].first;
        const uint32_t count = nodes[node].count;
        if (count == 0) {
            const float entry_a = box_entry(&box, nodes + first, selection.window_end);
            const float entry_b = box_entry(&box, nodes + first + 1, selection.window_end);
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
                                        load_float3(triangles[i].v2), t_max, &candidate) ||
                    !WF_HIT_PASSES(triangles, (int32_t)i, &candidate))
                    continue;
                select_hit(&selection, &candidate, (int32_t)i, triangles[i].light >= 0);
                if (stop_at_first_hit) return selected_hit(&selection);
            }
        }
        if (stack_size == 0) return selected_hit(&selection);
        node = stack[--stack_size];
    }
}

WF_INLINE RayHit bvh_closest_hit(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const Triangle* triangles,
                                 float3 origin, float3 direction, float t_max WF_HIT_FILTER_PARAM) {
    return bvh_traverse(nodes, triangles, origin, direction, t_max, 0 WF_HIT_FILTER_ARG);
}

/* 1 if any triangle is hit with t in (0, t_max). */
WF_INLINE int bvh_any_hit(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const Triangle* triangles, float3 origin,
                          float3 direction, float t_max WF_HIT_FILTER_PARAM) {
    return bvh_traverse(nodes, triangles, origin, direction, t_max, 1 WF_HIT_FILTER_ARG).triangle >= 0;
}

WF_DEVICE_END

#endif /* WF_BVH_TRAVERSE_H */
