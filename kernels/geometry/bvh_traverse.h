/* bvh_traverse.h — closest-hit and any-hit queries of a ray against the BVH
 * built by host/bvh/bvh_builder.h, shared by the kernels and the host.
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
 * emitter hit (a light entry >= 0) inside it wins over the closest hit. So a
 * light exactly coplanar with the surface it is set in is found wherever its
 * bound is no larger than the surface's, and in practice everywhere, since the
 * bounds are conservative several times over (tests/render/test_coplanar.cpp checks
 * every pixel); the two no longer take turns from pixel to pixel as their
 * roundings fall. The emitter wins, not the surface, because next-event
 * estimation reaches it (its shadow segment stops short of that plane), and
 * MIS weighs each light sample against the chance that BRDF sampling hits
 * the same light: that direction must find the light, or light is lost.
 * Every part of the rule is a least value or a comparison with one, so it is
 * the same in any order, and the window's end can cull boxes: no node beyond
 * it can change the answer. Nor can a hit whose t is beyond it: that hit is
 * not the closest, is not an emitter inside the window, and leaves the
 * window's end where it is; so the leaf test drops such lanes before it
 * bounds their error.
 *
 * The box test must never cull a node holding a triangle that the triangle
 * test hits. Four things could make it do so, and each is answered:
 *  - Its own rounding: the far distance is scaled by 1 + 2^-21 >= 1 + 2 gamma_3
 *    (Ize, "Robust BVH Ray Traversal", JCGT 2013; pbrt-v4).
 *  - The triangle test's rounding, which acts like moving each vertex by up to
 *    4 ulps of its distance from the origin (Woop et al. 2013, section 5), and
 *    moves t by as much. Every box is grown by four times that:
 *    pad = 2^-20 (16 ulps) x (the scene box's reach from the origin + |origin|).
 *    It costs nothing per node: the origin used against lower planes moves up
 *    by pad, the one used against upper planes down.
 *  - A direction component of 0: a moved origin on a plane of that axis
 *    would give 0 * infinity = NaN, and OpenCL leaves min and max of NaN
 *    undefined. The reciprocal is clamped to +-FLT_MAX instead, which keeps
 *    the arithmetic free of NaN; since the growth keeps a ray inside a slab at
 *    least pad from its planes, it leaves the slab only at pad * FLT_MAX,
 *    beyond every hit.
 *  - Coordinates so large that origin +- pad overflows: infinite origins
 *    would make every slab the whole line, so every box is met outright
 *    (child_entries), as it would be then.
 *
 * Layout (include/wavefront/scene_types.h, host/bvh/bvh_builder.h): nodes are 8
 * wide, and one visit tests the ray against all eight child boxes at once in
 * float8 lanes: one vload8 per plane row, with the planes the ray enters by
 * chosen per axis once per ray (as min and max of the two distances would
 * choose them), so an unused slot's empty box of infinities is simply missed.
 * Node 0 has one slot, the scene's box (whence the pad) over the top of the
 * tree, where traversal starts. A leaf is a run of up to eight consecutive
 * BVH positions in one or two TriangleBlocks (host/bvh/leaf_blocks.h): the
 * triangle test (geometry/triangle_intersect.h) takes a block's four lanes at
 * once, its corners loaded as rows chosen for the ray as the box rows are, and
 * reports only the lanes of the leaf; traversal keeps no copy of the
 * triangles.
 *
 * Order of visits: a visit goes straight on to the nearest child it meets,
 * whose hits may cull the others, and pushes the others as they come (a full
 * sort of them bought nothing measurable, bench/results/ray-throughput.md);
 * an any-hit query, which its first hit ends wherever it is, goes on to the
 * last slot met, the smallest box met (the collapse puts a node's children in
 * slots of decreasing area, host/bvh/bvh_builder.cpp: faster for shadow rays
 * than the binary tree's order). Each pending child keeps where the ray
 * enters its box, and is dropped when popped if the window's end has since
 * fallen below that entry:
 * the box test itself would now fail (its exit is scaled by the same
 * 1 + 2^-21), so nothing is culled that the test would keep. The stack holds
 * WF_BVH_STACK_SIZE children; the builder gives every subtree no more than
 * the room left to it (host/bvh/bvh_builder.cpp says how).
 *
 * A GPU's program (WF_GPU_TRAVERSAL) visits in the same order, but its
 * stack holds groups, not children: a node and the slots of it still to
 * visit (Ylitie et al. 2017), a pop taking the highest and leaving the rest,
 * so it holds at most one entry per level of the path. It lives in the
 * work-group's local memory (Aila and Laine 2009), WF_GPU_STACK_SIZE groups a
 * ray, where 64 children in private memory took scratch. A full stack drops
 * its bottom group, and once the rest is done, a walk (rebuild_step) goes
 * again from the top of the tree to the last slot taken, pushing at each
 * node the slots that come after the path's in that order: the dropped
 * groups, less what the window now culls (a shrunk window culls a suffix of
 * the nearest-first order, so the path's slot keeps its place). The walk finds the path
 * from node indices alone (host/bvh/bvh_builder.cpp lays each subtree out
 * after its node, children in slot order). It drops no popped child by its
 * entry: culling is only ever a saving, so the hits are the same. It tests a
 * node's boxes one at a time (child_slots_met), keeping the nearest as it
 * goes, where eight at once held forty-eight planes in registers; and a
 * leaf's triangles one at a time (triangle_intersect.h), each against the
 * window the ones before it left: a hit beyond the window cannot change the
 * answer (above), so that too is only a saving. Its selection keeps a hit's
 * t and triangle, not u and v: traversal_hit tests the one triangle selected
 * again at the end, and the same test of the same triangle gives the same
 * bits.
 *
 * On the device every query takes a HitFilter (materials/alpha_mask.h): a hit
 * it rejects (a transparent texel of an alpha-masked material) is as if the
 * triangle were not there. The host's queries, for the tests, have none.
 *
 * Two levels (WF_TWO_LEVEL; host/bvh/instance_bvh.h). A scene with shared
 * meshes has a top tree whose leaves are placements (Instance), one a leaf,
 * each a mesh's own tree in the mesh's space under its node `root`. A visit
 * of a top leaf maps the ray into the placement's space (enter_instance) and
 * goes on down the mesh's tree on the same stack, above the top tree's
 * entries; once the stack is back to where it entered, the ray is the world's
 * again (leave_instance). The mapped direction is not made unit, so t along
 * either ray is the same parameter, and the window's end and the pending
 * entries cull in both trees alike. The promise above holds per placement:
 * the selected hit is what testing every triangle of every placement against
 * the ray mapped as enter_instance maps it, and selecting as above (the
 * placement after the triangle index in the order), would give. Each tree is
 * built for the whole WF_BVH_STACK_SIZE, so the stack holds twice that. The
 * box test of the top tree sees the placements' boxes grown for the maps'
 * rounding (instance_bvh.cpp says by how much, and where that falls short:
 * rays from far beyond a placement stretched more than about 5 times). */
#ifndef WF_BVH_TRAVERSE_H
#define WF_BVH_TRAVERSE_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"
#include "geometry/triangle_intersect.h"
#include "geometry/triangle_blocks.h"
#include "geometry/trace_width.h"

/* What a query reads beyond the nodes and triangles: on the device the
 * scene, for its alpha masks and, in a two-level tree (WF_TWO_LEVEL), its
 * placements; on the host the placements alone, or none (null) for a tree of
 * one level, which is the default of the entry points at the end. */
#ifdef __OPENCL_C_VERSION__
#include "materials/alpha_mask.h"
#define WF_TRAVERSAL_SCENE_PARAM , const HitFilter* filter
#define WF_TRAVERSAL_SCENE_ARG , filter
#define WF_TRAVERSAL_SCENE_PARAM_OR_NONE WF_TRAVERSAL_SCENE_PARAM
#define WF_HIT_PASSES(triangles, i, hit) hit_passes_filter(filter, triangles, i, (hit)->u, (hit)->v)
#define WF_PLACEMENTS (filter->instances)
#define WF_TWO_LEVEL WF_HAS_INSTANCES
#else
#define WF_TRAVERSAL_SCENE_PARAM , const Instance* instances
#define WF_TRAVERSAL_SCENE_ARG , instances
#define WF_TRAVERSAL_SCENE_PARAM_OR_NONE , const Instance* instances = 0
#define WF_HIT_PASSES(triangles, i, hit) ((void)instances, 1) /* every hit passes; a leaf test reads no placement */
#define WF_PLACEMENTS instances
#define WF_TWO_LEVEL 1
#endif
#include "geometry/instance_map.h"

#if WF_TWO_LEVEL && WF_GPU_TRAVERSAL
#error "a GPU's traversal walks one tree: the host flattens a scene's instances for it (render/device_renderer.h)"
#endif

/* Pending children, pushed by a node visit that meets several; see above.
 * A two-level query's stack holds the top tree's and, above them, those of
 * the placement it is in, each tree built for the whole of WF_BVH_STACK_SIZE. */
#define WF_BVH_STACK_SIZE 64
#define WF_TRAVERSAL_STACK_SIZE (WF_TWO_LEVEL ? 2 * WF_BVH_STACK_SIZE : WF_BVH_STACK_SIZE)

#if WF_GPU_TRAVERSAL
/* A GPU's pending groups a ray (see above): 12 of 5 bytes for each of 64
 * work-items keep a work-group's local memory within 4 KiB, a sixteenth of
 * a gfx90a compute unit's, so that it does not limit occupancy below the
 * four waves a SIMD intersect's registers allow. A test build may shrink it
 * to run the rebuild often. */
#ifndef WF_GPU_STACK_SIZE
#define WF_GPU_STACK_SIZE 12
#endif
/* The local memory a kernel declares for its work-items' stacks, in entries;
 * WF_TRAVERSAL_LOCAL_SIZE is the launch's local size (the host's -D). */
#define WF_TRAVERSAL_STACK_ENTRIES (WF_GPU_STACK_SIZE * WF_TRAVERSAL_LOCAL_SIZE * WF_TRACE_WIDTH)
#endif

WF_DEVICE_BEGIN

typedef struct RayHit {
    float t;
    float u; /* barycentrics as in TriangleHit */
    float v;
    int32_t triangle; /* -1 on a miss, else an index into the BVH-ordered triangles */
#if WF_TWO_LEVEL
    int32_t instance; /* the placement whose triangle it is (-1 in a tree of one level) */
#endif
} RayHit;

/* A ray prepared for slab tests against boxes grown as described above. Per
 * axis, the planes it enters a box by (lower ones where the direction is
 * positive) and the origin moved for them; likewise for the planes it leaves
 * by. */
typedef struct BoxRay {
    float3 near_origin;
    float3 far_origin;
    float3 inv_direction;
    int near_row[3]; /* rows of BvhNode.bounds; the far row is near_row ^ 1 */
    int unbounded;   /* origin +- pad overflowed: every box is met */
} BoxRay;

/* `nodes` is the BVH: its node 0 holds the scene's box in slot 0. */
WF_INLINE BoxRay box_ray(WF_GLOBAL const BvhNode* nodes, float3 origin, float3 direction) {
    const float3 lo = make_float3(nodes->bounds[0][0], nodes->bounds[2][0], nodes->bounds[4][0]);
    const float3 hi = make_float3(nodes->bounds[1][0], nodes->bounds[3][0], nodes->bounds[5][0]);
    const float3 reach = max(fabs(lo - origin), fabs(hi - origin));
    /* The |origin| term keeps origin +- pad some ulps away from origin, so the
     * growth survives rounding however far the scene is from the world origin. */
    const float3 offset = fabs(origin);
    const float pad = 0x1p-20f * (reach.x + reach.y + reach.z + offset.x + offset.y + offset.z);
    const float flt_max = 0x1.fffffep127f;
    const float3 origin_lo = origin + pad; /* for distances to lower planes */
    const float3 origin_hi = origin - pad; /* for distances to upper planes */
    BoxRay ray;
    ray.inv_direction = max(min(1.0f / direction, make_float3(flt_max, flt_max, flt_max)),
                            make_float3(-flt_max, -flt_max, -flt_max));
    /* Never 0 nor NaN, so its sign says which planes come first. Taking them
     * so is what min and max of the two distances would take, since rounding
     * keeps their order; and it lets an empty box's infinities miss. */
    const int flip_x = ray.inv_direction.x < 0.0f, flip_y = ray.inv_direction.y < 0.0f,
              flip_z = ray.inv_direction.z < 0.0f;
    ray.near_origin = make_float3(flip_x ? origin_hi.x : origin_lo.x, flip_y ? origin_hi.y : origin_lo.y,
                                  flip_z ? origin_hi.z : origin_lo.z);
    ray.far_origin = make_float3(flip_x ? origin_lo.x : origin_hi.x, flip_y ? origin_lo.y : origin_hi.y,
                                 flip_z ? origin_lo.z : origin_hi.z);
    ray.near_row[0] = flip_x;
    ray.near_row[1] = 2 + flip_y;
    ray.near_row[2] = 4 + flip_z;
    const float3 moved = max(fabs(origin_lo), fabs(origin_hi));
    ray.unbounded = !(max(max(moved.x, moved.y), moved.z) <= flt_max);
    return ray;
}

/* The children whose box the ray meets before t_limit, as bit i for slot i,
 * and in entry[i] where it enters slot i's box. */
WF_FORCE_INLINE uint32_t child_entries(const BoxRay* ray, WF_GLOBAL const BvhNode* node, float t_limit,
                                       float* entry) {
    if (ray->unbounded) {
        /* Every slab is the whole line, as infinite origins make it. But an
         * unused slot's infinities would meet them as inf - inf = NaN, so its
         * child word, 0 only there, says which slots hold a box. */
        uint32_t used = 0u;
        for (int i = 0; i < WF_BVH_WIDTH; ++i) {
            entry[i] = 0.0f;
            used |= (node->child[i] != 0u ? 1u : 0u) << i;
        }
        return used;
    }
    const float8 near_x = (vload8(0, node->bounds[ray->near_row[0]]) - ray->near_origin.x) * ray->inv_direction.x;
    const float8 near_y = (vload8(0, node->bounds[ray->near_row[1]]) - ray->near_origin.y) * ray->inv_direction.y;
    const float8 near_z = (vload8(0, node->bounds[ray->near_row[2]]) - ray->near_origin.z) * ray->inv_direction.z;
    const float8 far_x = (vload8(0, node->bounds[ray->near_row[0] ^ 1]) - ray->far_origin.x) * ray->inv_direction.x;
    const float8 far_y = (vload8(0, node->bounds[ray->near_row[1] ^ 1]) - ray->far_origin.y) * ray->inv_direction.y;
    const float8 far_z = (vload8(0, node->bounds[ray->near_row[2] ^ 1]) - ray->far_origin.z) * ray->inv_direction.z;
    const float8 enter = max(max(near_x, near_y), max(near_z, 0.0f));
    const float8 exit = min(min(far_x, far_y), min(far_z, t_limit)) * (1.0f + 0x1p-21f);
    vstore8(enter, 0, entry);
    return lane_bits8(islessequal(enter, exit));
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
#if WF_TWO_LEVEL
    s.closest.instance = -1;
#endif
    s.emitter = s.closest;
    s.window_end = t_max;
    return s;
}

/* Whether a hit at t on triangle `index` of placement `instance` comes
 * before `than` (none yet: -1 at t_max, which every hit is below): least t,
 * then lower index, then lower placement. */
WF_FORCE_INLINE int comes_before(float t, int32_t index, int32_t instance, const RayHit* than) {
#if WF_TWO_LEVEL
    return t < than->t ||
           (t == than->t && (index < than->triangle || (index == than->triangle && instance < than->instance)));
#else
    return t < than->t || (t == than->t && index < than->triangle);
#endif
}

WF_FORCE_INLINE void select_hit(HitSelection* s, const TriangleHit* hit, int32_t index, int32_t instance,
                                int emitter) {
    RayHit h;
    h.t = hit->t;
#if WF_GPU_TRAVERSAL
    /* Left 0 until traversal_hit: the barycentrics of two hits, kept
     * through a GPU's whole traversal, held 10 registers of intersect. */
    h.u = 0.0f;
    h.v = 0.0f;
#else
    h.u = hit->u;
    h.v = hit->v;
#endif
    h.triangle = index;
#if WF_TWO_LEVEL
    h.instance = instance;
#endif
    if (comes_before(h.t, index, instance, &s->closest)) s->closest = h;
    if (emitter && comes_before(h.t, index, instance, &s->emitter)) s->emitter = h;
    s->window_end = min(s->window_end, hit->t + 2.0f * hit->t_error);
}

WF_INLINE RayHit selected_hit(const HitSelection* s) {
    return s->emitter.triangle >= 0 && s->emitter.t <= s->window_end ? s->emitter : s->closest;
}

/* A block's four triangles in float4 lanes, each corner permuted for the ray
 * as the test wants it: a row a coordinate, chosen as the box test chooses
 * its planes. */
WF_FORCE_INLINE TriangleLanes block_lanes(const WatertightRay* ray, WF_GLOBAL const TriangleBlock* block) {
    TriangleLanes lanes;
    lanes.v0.x = vload4(0, block->corners[ray->kx]);
    lanes.v0.y = vload4(0, block->corners[ray->ky]);
    lanes.v0.z = vload4(0, block->corners[ray->kz]);
    lanes.v1.x = vload4(0, block->corners[3 + ray->kx]);
    lanes.v1.y = vload4(0, block->corners[3 + ray->ky]);
    lanes.v1.z = vload4(0, block->corners[3 + ray->kz]);
    lanes.v2.x = vload4(0, block->corners[6 + ray->kx]);
    lanes.v2.y = vload4(0, block->corners[6 + ray->ky]);
    lanes.v2.z = vload4(0, block->corners[6 + ray->kz]);
    return lanes;
}

#if WF_GPU_TRAVERSAL
/* Lane `lane` of a block, permuted for the ray as block_lanes permutes them. */
WF_FORCE_INLINE TriangleLanes_x1 block_lane(const WatertightRay* ray, WF_GLOBAL const TriangleBlock* block,
                                            uint32_t lane) {
    TriangleLanes_x1 one;
    one.v0.x = block->corners[ray->kx][lane];
    one.v0.y = block->corners[ray->ky][lane];
    one.v0.z = block->corners[ray->kz][lane];
    one.v1.x = block->corners[3 + ray->kx][lane];
    one.v1.y = block->corners[3 + ray->ky][lane];
    one.v1.z = block->corners[3 + ray->kz][lane];
    one.v2.x = block->corners[6 + ray->kx][lane];
    one.v2.y = block->corners[6 + ray->ky][lane];
    one.v2.z = block->corners[6 + ray->kz][lane];
    return one;
}
#endif

/* The lanes of block `block` that hold positions [first, end), as bit i for lane i. */
WF_FORCE_INLINE uint32_t lanes_in_range(uint32_t block, uint32_t first, uint32_t end) {
    const uint32_t base = block * WF_BLOCK_LANES;
    const uint32_t lo = first > base ? first - base : 0u;
    const uint32_t hi = end - base < WF_BLOCK_LANES ? end - base : WF_BLOCK_LANES;
    return ((1u << hi) - 1u) & ~((1u << lo) - 1u);
}

/* A pushed child is met later: its memory can be on its way meanwhile. */
WF_FORCE_INLINE void prefetch_child(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const TriangleBlock* blocks,
                                    uint32_t child) {
    WF_GLOBAL const char* p = (child & WF_BVH_LEAF)
                                  ? (WF_GLOBAL const char*)block_of(blocks, child & WF_BVH_FIRST_MASK)
                                  : (WF_GLOBAL const char*)(nodes + child);
    WF_PREFETCH(p);
    WF_PREFETCH(p + 64);
    WF_PREFETCH(p + 128);
    WF_PREFETCH(p + 192);
}

WF_FORCE_INLINE uint32_t lowest_bit(uint32_t bits) { return 31u - clz(bits & (0u - bits)); }

#if !WF_GPU_TRAVERSAL
/* The leaf of BVH positions [first, end) against one ray, a block's four
 * triangles at a time, each hit handed to select_hit; returns 1 at the first
 * hit when stop_at_first_hit is set. */
WF_FORCE_INLINE int leaf_hits(const WatertightRay* ray, WF_GLOBAL const TriangleBlock* triangles, uint32_t first,
                              uint32_t end, int32_t instance, float t_max, HitSelection* selection,
                              int stop_at_first_hit WF_TRAVERSAL_SCENE_PARAM) {
    for (uint32_t block = first / WF_BLOCK_LANES; block * WF_BLOCK_LANES < end; ++block) {
        WF_GLOBAL const TriangleBlock* b = triangles + block;
        const TriangleLanes lanes = block_lanes(ray, b);
        TriangleHit hits[WF_BLOCK_LANES];
        uint32_t found = intersect_triangles(ray, &lanes, lanes_in_range(block, first, end), t_max,
                                             selection->window_end, hits);
        for (; found != 0u; found &= found - 1u) {
            const uint32_t lane = lowest_bit(found);
            const int32_t index = (int32_t)(block * WF_BLOCK_LANES + lane);
            if (!WF_HIT_PASSES(triangles, index, &hits[lane])) continue;
            select_hit(selection, &hits[lane], index, instance, b->light[lane] >= 0);
            if (stop_at_first_hit) return 1;
        }
    }
    return 0;
}
#endif

#if WF_GPU_TRAVERSAL
/* child_entries one slot at a time, as a GPU's program tests the boxes: one
 * box's six planes live while it is tested, where eight boxes' forty-eight in
 * vector registers cost the GPU its occupancy (bench/results/gpu-isa.md).
 * Each slot's arithmetic is child_entries' lane's, so the same slots are met.
 * Returns them, and in *next the one to visit first: the nearest (the lowest
 * slot of equal entries, as the CPU's loop chooses it), or the last met when
 * `last` is set (an any-hit query). */
WF_FORCE_INLINE uint32_t child_slots_met(const BoxRay* ray, WF_GLOBAL const BvhNode* node, float t_limit, int last,
                                         uint32_t* next) {
    uint32_t met = 0u;
    float nearest = INFINITY;
    *next = 0u;
    for (uint32_t i = 0u; i < WF_BVH_WIDTH; ++i) {
        float enter = 0.0f; /* every used slot is met where the origin is unbounded (child_entries) */
        if (ray->unbounded) {
            if (node->child[i] == 0u) continue;
        } else {
            const float near_x = (node->bounds[ray->near_row[0]][i] - ray->near_origin.x) * ray->inv_direction.x;
            const float near_y = (node->bounds[ray->near_row[1]][i] - ray->near_origin.y) * ray->inv_direction.y;
            const float near_z = (node->bounds[ray->near_row[2]][i] - ray->near_origin.z) * ray->inv_direction.z;
            const float far_x = (node->bounds[ray->near_row[0] ^ 1][i] - ray->far_origin.x) * ray->inv_direction.x;
            const float far_y = (node->bounds[ray->near_row[1] ^ 1][i] - ray->far_origin.y) * ray->inv_direction.y;
            const float far_z = (node->bounds[ray->near_row[2] ^ 1][i] - ray->far_origin.z) * ray->inv_direction.z;
            enter = max(max(near_x, near_y), max(near_z, 0.0f));
            const float exit = min(min(far_x, far_y), min(far_z, t_limit)) * (1.0f + 0x1p-21f);
            if (!(enter <= exit)) continue;
        }
        met |= 1u << i;
        if (last || enter < nearest) {
            nearest = enter;
            *next = i;
        }
    }
    return met;
}
#endif

/* One ray's traversal between visits, so that it can be resumed: two rays
 * may take turns (bvh_traverse_pair; geometry/trace_width.h says when). The
 * pending children are kept apart, since an array in the struct would keep
 * the rest of it from living in registers. */
typedef struct Traversal {
    WatertightRay ray;
    BoxRay box;
    HitSelection selection;
    float t_max;
    uint32_t child; /* the next child to visit */
    int stack_size;
#if WF_TWO_LEVEL
    float3 world_origin, world_direction; /* the ray as asked, kept while ray and box are a placement's */
    int32_t instance;  /* the placement whose tree it is in; -1 in the top tree */
    int instance_base; /* the stack's size when it went into the placement's tree */
#endif
#if WF_GPU_TRAVERSAL
    uint32_t node; /* the node `child` was taken from (0: none yet), */
    uint32_t slot; /* and its slot there */
    int lost;      /* bit 0: a full stack has dropped a group since the last rebuild;
                      bit 1: `child` is a node of the rebuild's walk (rebuild_step) */
#endif
} Traversal;

#if WF_GPU_TRAVERSAL
/* A ray's pending groups in the work-group's local memory (the kernel
 * declares it: kernel_params.h), entry i at [i * WF_TRAVERSAL_LOCAL_SIZE]. */
typedef struct TraversalStack {
    __local uint* node;
    __local uchar* slots;
} TraversalStack;

/* The stack of ray `ray` of this work-item. */
WF_INLINE TraversalStack traversal_stack(const HitFilter* scene, uint32_t ray) {
    const uint32_t first = ray * WF_GPU_STACK_SIZE * WF_TRAVERSAL_LOCAL_SIZE + (uint32_t)get_local_id(0);
    TraversalStack stack;
    stack.node = scene->traversal_nodes + first;
    stack.slots = scene->traversal_slots + first;
    return stack;
}

/* Pushes node `node`'s slots `slots`; a full stack drops its bottom group first. */
WF_FORCE_INLINE void push_group(Traversal* t, const TraversalStack* stack, uint32_t node, uint32_t slots) {
    if (t->stack_size == WF_GPU_STACK_SIZE) {
        for (int i = 1; i < WF_GPU_STACK_SIZE; ++i) {
            stack->node[(i - 1) * WF_TRAVERSAL_LOCAL_SIZE] = stack->node[i * WF_TRAVERSAL_LOCAL_SIZE];
            stack->slots[(i - 1) * WF_TRAVERSAL_LOCAL_SIZE] = stack->slots[i * WF_TRAVERSAL_LOCAL_SIZE];
        }
        --t->stack_size;
        t->lost |= 1;
    }
    stack->node[t->stack_size * WF_TRAVERSAL_LOCAL_SIZE] = node;
    stack->slots[t->stack_size * WF_TRAVERSAL_LOCAL_SIZE] = (uchar)slots;
    ++t->stack_size;
}

/* Goes on to slot `slot` of node `node`. */
WF_FORCE_INLINE void take_slot(Traversal* t, WF_GLOBAL const BvhNode* nodes, uint32_t node, uint32_t slot) {
    t->node = node;
    t->slot = slot;
    t->child = nodes[node].child[slot];
}

/* The slots of `node` still to visit once the path below it has gone
 * through slot `taken`, in the order of visits: the first child, then the
 * others from the highest slot down. `met` and `first` as child_slots_met
 * gives them now. */
WF_FORCE_INLINE uint32_t slots_after(uint32_t met, uint32_t first, uint32_t taken) {
    return met & ~(1u << first) & (taken == first ? ~0u : (1u << taken) - 1u);
}

/* One node of the rebuild's walk from the top of the tree to the last slot
 * taken (t->node, t->slot), which pushes again every group that path still
 * holds: the groups a full stack dropped, now culled by the present window.
 * `met` and `first` are node `n`'s, as child_slots_met gives them. Interior
 * children follow their node in slot order, each subtree's nodes
 * consecutive (host/bvh/bvh_builder.cpp), so the path's slot at a node is
 * that of its greatest interior child at or below t->node. Returns the next
 * node of the walk, 0 at its end. */
WF_FORCE_INLINE uint32_t rebuild_step(Traversal* t, const TraversalStack* stack, WF_GLOBAL const BvhNode* node,
                                      uint32_t n, uint32_t met, uint32_t first) {
    uint32_t taken = t->slot, below = 0u;
    if (n != t->node)
        for (uint32_t i = 0u; i < WF_BVH_WIDTH; ++i) {
            const uint32_t c = node->child[i];
            if (c != 0u && !(c & WF_BVH_LEAF) && c <= t->node && c > below) {
                below = c;
                taken = i;
            }
        }
    const uint32_t pending = slots_after(met, first, taken);
    if (pending != 0u) push_group(t, stack, n, pending);
    return n == t->node ? 0u : node->child[taken];
}

/* The whole walk at once, as an any-hit query rebuilds its stack. */
WF_FORCE_INLINE void rebuild_stack(Traversal* t, const TraversalStack* stack, WF_GLOBAL const BvhNode* nodes) {
    for (uint32_t n = nodes->child[0]; n != 0u;) {
        uint32_t first;
        const uint32_t met = child_slots_met(&t->box, nodes + n, t->selection.window_end, 1, &first);
        n = rebuild_step(t, stack, nodes + n, n, met, first);
    }
}
#else
typedef struct TraversalStack {
    uint32_t child[WF_TRAVERSAL_STACK_SIZE];
    float entry[WF_TRAVERSAL_STACK_SIZE];
} TraversalStack;
#endif

WF_FORCE_INLINE void traversal_start(Traversal* t, WF_GLOBAL const BvhNode* nodes, float3 origin, float3 direction,
                                     float t_max) {
    t->ray = watertight_ray(origin, direction);
    t->box = box_ray(nodes, origin, direction);
    t->selection = no_hits(t_max);
    t->t_max = t_max;
    t->stack_size = 0;
#if WF_TWO_LEVEL
    t->world_origin = origin;
    t->world_direction = direction;
    t->instance = -1;
    t->instance_base = 0;
#endif
#if WF_GPU_TRAVERSAL
    t->node = 0u;
    t->slot = 0u;
    t->lost = 0;
#endif
    /* Node 0's one child, the top of the tree: its own boxes test the ray
     * against the scene's. */
    t->child = nodes->child[0];
}

#if WF_TWO_LEVEL
/* Goes into the tree of placement i (a leaf of the top tree holds one): the
 * ray mapped into its mesh's space, its direction not made unit,
 * so that t along it is t along the ray as asked, and the window's end and
 * the pending entries mean the same in both trees. Its box ray pads by the
 * mesh's box, as the top tree's by the scene's. */
WF_FORCE_INLINE void enter_instance(Traversal* t, WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const Instance* placements,
                                    uint32_t i) {
    WF_GLOBAL const Instance* placement = placements + i;
    const float3 origin = map_point(placement->world_to_object, t->world_origin);
    const float3 direction = map_vector(placement->world_to_object, t->world_direction);
    t->ray = watertight_ray(origin, direction);
    t->box = box_ray(nodes + placement->root, origin, direction);
    t->child = nodes[placement->root].child[0];
    t->instance = (int32_t)i;
    t->instance_base = t->stack_size;
}

/* Back in the top tree, the ray as asked. */
WF_FORCE_INLINE void leave_instance(Traversal* t, WF_GLOBAL const BvhNode* nodes) {
    t->ray = watertight_ray(t->world_origin, t->world_direction);
    t->box = box_ray(nodes, t->world_origin, t->world_direction);
    t->instance = -1;
}
#endif

#if WF_GPU_TRAVERSAL
/* selected_hit with the u and v that a GPU's selection leaves 0: the one
 * selected triangle tested again, which gives the bits its first test gave. */
WF_INLINE RayHit traversal_hit(const Traversal* t, WF_GLOBAL const TriangleBlock* triangles) {
    RayHit h = selected_hit(&t->selection);
    if (h.triangle >= 0) {
        const TriangleLanes_x1 one = block_lane(&t->ray, triangles + h.triangle / WF_BLOCK_LANES,
                                                (uint32_t)h.triangle % WF_BLOCK_LANES);
        TriangleHit hit;
        intersect_triangles_x1(&t->ray, &one, 1u, t->t_max, t->t_max, &hit);
        h.u = hit.u;
        h.v = hit.v;
    }
    return h;
}
#endif

/* One leaf or one node visit; returns 1 once the answer is
 * selected_hit(&t->selection) (a GPU's: traversal_hit): every child visited, or, when
 * stop_at_first_hit is set, the first hit found. */
WF_FORCE_INLINE int traversal_step(Traversal* t, TraversalStack* stack, WF_GLOBAL const BvhNode* nodes,
                                    WF_GLOBAL const TriangleBlock* triangles,
                                    int stop_at_first_hit WF_TRAVERSAL_SCENE_PARAM) {
    const uint32_t child = t->child;
    if (child & WF_BVH_LEAF) {
        const uint32_t first = child & WF_BVH_FIRST_MASK;
        const uint32_t end = first + ((child & ~WF_BVH_LEAF) >> WF_BVH_COUNT_SHIFT) + 1u;
#if WF_GPU_TRAVERSAL
        /* One triangle at a time, each culled by the window the ones before it
         * left, in one flat loop: a loop over blocks around one over their
         * lanes held 36 more registers (bench/results/gpu-isa.md). */
        for (uint32_t position = first; position < end; ++position) {
            WF_GLOBAL const TriangleBlock* b = triangles + position / WF_BLOCK_LANES;
            const uint32_t lane = position % WF_BLOCK_LANES;
            const TriangleLanes_x1 one = block_lane(&t->ray, b, lane);
            TriangleHit hit;
            if (!intersect_triangles_x1(&t->ray, &one, 1u, t->t_max, t->selection.window_end, &hit)) continue;
            if (!WF_HIT_PASSES(triangles, (int32_t)position, &hit)) continue;
            if (stop_at_first_hit) {
                /* The answer, as select_hit would select it alone; written
                 * here, the rest of the selection is not kept through a shadow
                 * ray's traversal, where it held 22 registers. */
                t->selection.closest.t = hit.t;
                t->selection.closest.triangle = (int32_t)position;
                return 1;
            }
            select_hit(&t->selection, &hit, (int32_t)position, -1, b->light[lane] >= 0);
        }
#else
#if WF_TWO_LEVEL
        if (t->instance < 0 && WF_PLACEMENTS) { /* the top tree's leaf: one placement */
            enter_instance(t, nodes, WF_PLACEMENTS, first);
            return 0;
        }
        const int32_t instance = t->instance;
#else
        const int32_t instance = -1;
#endif
        /* One or two blocks, four triangles at a time. */
        if (leaf_hits(&t->ray, triangles, first, end, instance, t->t_max, &t->selection,
                      stop_at_first_hit WF_TRAVERSAL_SCENE_ARG))
            return 1;
#endif
    } else {
        WF_GLOBAL const BvhNode* node = nodes + child;
#if WF_GPU_TRAVERSAL
        uint32_t next;
        const uint32_t met = child_slots_met(&t->box, node, t->selection.window_end, stop_at_first_hit, &next);
        if (!stop_at_first_hit && (t->lost & 2)) { /* a node of the walk (below), tested as a visit's */
            const uint32_t walk = rebuild_step(t, stack, node, child, met, next);
            if (walk != 0u) {
                t->child = walk;
                return 0;
            }
            t->lost &= 1;
        } else if (met != 0u) { /* on to the nearest (see above), the others pushed as one group */
            if (met != 1u << next) push_group(t, stack, child, met & ~(1u << next));
            take_slot(t, nodes, child, next);
            return 0;
        }
#else
        float entry[WF_BVH_WIDTH];
        const uint32_t met = child_entries(&t->box, node, t->selection.window_end, entry);
        if (met != 0u) { /* on to the nearest (see above), the others pushed */
            uint32_t next = stop_at_first_hit ? 31u - clz(met) : lowest_bit(met);
            if (!stop_at_first_hit)
                for (uint32_t m = met & (met - 1u); m != 0u; m &= m - 1u) {
                    const uint32_t slot = lowest_bit(m);
                    if (entry[slot] < entry[next]) next = slot;
                }
            for (uint32_t m = met & ~(1u << next); m != 0u; m &= m - 1u) {
                const uint32_t slot = lowest_bit(m);
                stack->entry[t->stack_size] = entry[slot];
                stack->child[t->stack_size] = node->child[slot];
#if WF_TWO_LEVEL
                if (t->instance < 0 && WF_PLACEMENTS && (node->child[slot] & WF_BVH_LEAF)) /* a placement */
                    WF_PREFETCH(WF_PLACEMENTS + (node->child[slot] & WF_BVH_FIRST_MASK));
                else
#endif
                    prefetch_child(nodes, triangles, stack->child[t->stack_size]);
                ++t->stack_size;
            }
            t->child = node->child[next];
            return 0;
        }
#endif
    }
    /* The next pending child, unless the window's end has moved below where
     * it enters its box since it was pushed: its box test would now fail,
     * since the limit scales as the test's own exit does. */
#if WF_GPU_TRAVERSAL
    if (t->stack_size == 0) {
        if (!t->lost) return 1;
        /* A closest-hit query walks a node a step, so that one box test serves
         * visits and walk (12 registers of intersect); an any-hit query walks
         * at once, its second box test costing fewer registers than a walk
         * kept across steps (4-6 of intersect_shadow). */
        if (!stop_at_first_hit) {
            t->lost = 2;
            t->child = nodes->child[0];
            return 0;
        }
        t->lost = 0;
        rebuild_stack(t, stack, nodes);
        if (t->stack_size == 0) return 1;
    }
    /* The top group's highest slot; the group stays while it has others. */
    const int top = (t->stack_size - 1) * WF_TRAVERSAL_LOCAL_SIZE;
    const uint32_t slots = stack->slots[top];
    const uint32_t slot = 31u - clz(slots);
    if (slots != 1u << slot)
        stack->slots[top] = (uchar)(slots & ~(1u << slot));
    else
        --t->stack_size;
    take_slot(t, nodes, stack->node[top], slot);
#else
    for (;;) {
#if WF_TWO_LEVEL
        /* A placement's tree done: back to the top tree. */
        if (t->instance >= 0 && t->stack_size == t->instance_base) leave_instance(t, nodes);
#endif
        if (t->stack_size == 0) return 1;
        --t->stack_size;
        if (!(stack->entry[t->stack_size] > t->selection.window_end * (1.0f + 0x1p-21f))) break;
    }
    t->child = stack->child[t->stack_size];
#endif
    return 0;
}

/* The selected hit in (0, t_max), or the first one found when
 * stop_at_first_hit is set. */
WF_INLINE RayHit bvh_traverse(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const TriangleBlock* triangles,
                              float3 origin, float3 direction, float t_max,
                              int stop_at_first_hit WF_TRAVERSAL_SCENE_PARAM_OR_NONE) {
    Traversal t;
#if WF_GPU_TRAVERSAL
    TraversalStack stack = traversal_stack(filter, 0u);
#else
    TraversalStack stack;
#endif
    traversal_start(&t, nodes, origin, direction, t_max);
    while (!traversal_step(&t, &stack, nodes, triangles, stop_at_first_hit WF_TRAVERSAL_SCENE_ARG)) {
    }
#if WF_GPU_TRAVERSAL
    return traversal_hit(&t, triangles);
#else
    return selected_hit(&t.selection);
#endif
}

/* Two rays' bvh_traverse, a step of each in turn (geometry/trace_width.h
 * says why). Each ray's steps are those of its own bvh_traverse, so each
 * answer is too. */
WF_INLINE void bvh_traverse_pair(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const TriangleBlock* triangles,
                                 const float3 origin[2], const float3 direction[2], float t_max,
                                 int stop_at_first_hit WF_TRAVERSAL_SCENE_PARAM, RayHit hit[2]) {
    Traversal a, b;
#if WF_GPU_TRAVERSAL
    TraversalStack stack_a = traversal_stack(filter, 0u), stack_b = traversal_stack(filter, 1u);
#else
    TraversalStack stack_a, stack_b;
#endif
    traversal_start(&a, nodes, origin[0], direction[0], t_max);
    traversal_start(&b, nodes, origin[1], direction[1], t_max);
    int a_done = 0, b_done = 0;
    while (!a_done && !b_done) {
        a_done = traversal_step(&a, &stack_a, nodes, triangles, stop_at_first_hit WF_TRAVERSAL_SCENE_ARG);
        b_done = traversal_step(&b, &stack_b, nodes, triangles, stop_at_first_hit WF_TRAVERSAL_SCENE_ARG);
    }
    while (!a_done) a_done = traversal_step(&a, &stack_a, nodes, triangles, stop_at_first_hit WF_TRAVERSAL_SCENE_ARG);
    while (!b_done) b_done = traversal_step(&b, &stack_b, nodes, triangles, stop_at_first_hit WF_TRAVERSAL_SCENE_ARG);
#if WF_GPU_TRAVERSAL
    hit[0] = traversal_hit(&a, triangles);
    hit[1] = traversal_hit(&b, triangles);
#else
    hit[0] = selected_hit(&a.selection);
    hit[1] = selected_hit(&b.selection);
#endif
}

/* bvh_traverse of `count` rays, 1 to WF_TRACE_WIDTH, into hit[0 .. count). */
WF_INLINE void bvh_traverse_rays(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const TriangleBlock* triangles,
                                 const float3* origin, const float3* direction, uint32_t count, float t_max,
                                 int stop_at_first_hit WF_TRAVERSAL_SCENE_PARAM, RayHit* hit) {
    if (WF_TRACE_WIDTH > 1 && count == 2u) {
        bvh_traverse_pair(nodes, triangles, origin, direction, t_max, stop_at_first_hit WF_TRAVERSAL_SCENE_ARG, hit);
        return;
    }
    hit[0] = bvh_traverse(nodes, triangles, origin[0], direction[0], t_max, stop_at_first_hit WF_TRAVERSAL_SCENE_ARG);
}

WF_INLINE RayHit bvh_closest_hit(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const TriangleBlock* triangles,
                                 float3 origin, float3 direction, float t_max WF_TRAVERSAL_SCENE_PARAM_OR_NONE) {
    return bvh_traverse(nodes, triangles, origin, direction, t_max, 0 WF_TRAVERSAL_SCENE_ARG);
}

/* 1 if any triangle is hit with t in (0, t_max). */
WF_INLINE int bvh_any_hit(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const TriangleBlock* triangles, float3 origin,
                          float3 direction, float t_max WF_TRAVERSAL_SCENE_PARAM_OR_NONE) {
    return bvh_traverse(nodes, triangles, origin, direction, t_max, 1 WF_TRAVERSAL_SCENE_ARG).triangle >= 0;
}

WF_DEVICE_END

#endif /* WF_BVH_TRAVERSE_H */
