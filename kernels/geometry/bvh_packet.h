/* bvh_packet.h — up to eight rays from one point traversed together, a ray a
 * lane (Wald et al. 2001; Benthin et al. 2012): a CPU's camera rays, whose
 * neighbours in a queue are neighbouring pixels. Device only, and only in a
 * CPU's program (a GPU's runs a ray a work-item: geometry/bvh_traverse.h).
 *
 * Promises: each ray's hit is the one bvh_closest_hit returns for it alone,
 * to the bit. The leaf test is that test's own, written for eight rays
 * against one triangle (geometry/triangle_lanes.inc at width 8): each lane
 * goes through the operations its ray's single test goes through. Which
 * triangles it meets does not change the answer, since the selection rule
 * (bvh_traverse.h) does not depend on the order of visits, and a hit found
 * in a box that a ray alone would have culled lies beyond its window: so a
 * packet may visit more than any one of its rays would, never less.
 *
 * How: one box test for the packet, conservative for all of its rays. Every
 * ray's distance to a plane is fl(fl(b - o) * r), o the moved origin (box_ray;
 * one for all, since the rays share their origin) and r the ray's clamped
 * reciprocal direction, and rounding is monotone; so from the lanes' least
 * and greatest r on each axis (of one sign, required) the least entry and
 * greatest exit over the lanes are bounded below and above by the same
 * operations on those extremes. A child that bound cannot cull is tested
 * again lane by lane (each lane's own child_entries, to the bit), so a lane
 * goes down only where its own box test lets it, and a child no lane meets is
 * dropped. A visit goes on to the child of least entry and pushes the
 * others, each with its lanes, dropped when popped if its entry has since
 * passed every lane's window, as bvh_traverse does, and asked for from
 * memory as it is pushed (on MetalRoughSpheres, whose 50 MB of triangles
 * miss the caches, 6-9% faster camera rays; the same on scenes that fit). A
 * leaf that WF_PACKET_LEAF_LANES lanes or more reach is tested a triangle at
 * a time against the packet; one that fewer reach, a ray at a time against
 * four triangles, as a lone ray tests it.
 *
 * Packets only where they pay: the rays must share an origin (camera rays
 * of a pinhole), the watertight test's permutation (the axis of each
 * direction's largest component) and the direction's sign on every axis;
 * else the caller traces them one by one. Rays with an unbounded origin
 * (box_ray) are never packed. */
#ifndef WF_BVH_PACKET_H
#define WF_BVH_PACKET_H

#include "wavefront/compat.h"
#include "geometry/bvh_traverse.h"

/* Packets walk one tree: a two-level tree's rays go one by one. */
#if !WF_GPU_TRAVERSAL && !WF_TWO_LEVEL
#define WF_PACKET_RAYS 8
/* Fewer rays than this go one by one: a packet's tests cost eight lanes. */
#ifndef WF_PACKET_MIN_RAYS
#define WF_PACKET_MIN_RAYS 4
#endif

/* The packet's box tests: the moved origins (one origin, so the same in
 * every lane), and per axis each lane's reciprocal direction and the
 * lanes' least and greatest. */
typedef struct PacketBox {
    float3 near_origin, far_origin;
    float8 inv_x, inv_y, inv_z;
    float3 inv_lo, inv_hi;
    int near_row[3]; /* as BoxRay's, the same in every lane */
} PacketBox;

typedef struct Packet {
    PacketRay ray;
    PacketBox box;
    WatertightRay first; /* lane 0's; with shear[] and scale[], each lane's, for a leaf few lanes reach */
    float shear_x[WF_PACKET_RAYS], shear_y[WF_PACKET_RAYS], scale_z[WF_PACKET_RAYS];
    uint32_t lanes; /* bit i: lane i holds a ray of the caller's */
} Packet;

/* Lane `r`'s WatertightRay, as watertight_ray gives it. */
WF_INLINE WatertightRay packet_lane_ray(const Packet* p, uint32_t r) {
    WatertightRay w = p->first;
    w.shear_x = p->shear_x[r];
    w.shear_y = p->shear_y[r];
    w.scale_z = p->scale_z[r];
    return w;
}

WF_INLINE float min_lane(float8 v) {
    const float4 a = min(v.lo, v.hi);
    return min(min(a.x, a.y), min(a.z, a.w));
}

WF_INLINE float max_lane(float8 v) {
    const float4 a = max(v.lo, v.hi);
    return max(max(a.x, a.y), max(a.z, a.w));
}

/* Row k (0: x, 1: y, 2: z) of three. */
WF_INLINE float8 packet_row(float8 x, float8 y, float8 z, int k) { return k == 0 ? x : (k == 1 ? y : z); }

/* Packs rays [0, count), 2 to WF_PACKET_RAYS of them, the rest of the lanes
 * repeating ray 0; 0 when they do not make a packet (see above). Each lane's
 * numbers are those watertight_ray and box_ray give its ray, computed by
 * the same operations eight at a time. */
WF_INLINE int packet_start(Packet* p, WF_GLOBAL const BvhNode* nodes, const float3* origin, const float3* direction,
                           uint32_t count) {
    for (uint32_t i = 1; i < count; ++i)
        if (any(origin[i] != origin[0])) return 0; /* the usual answer for rays other than a camera's: first */
    const BoxRay first = box_ray(nodes, origin[0], direction[0]);
    if (first.unbounded) return 0;
    float dx[WF_PACKET_RAYS], dy[WF_PACKET_RAYS], dz[WF_PACKET_RAYS];
    for (uint32_t i = 0; i < WF_PACKET_RAYS; ++i) {
        const uint32_t r = i < count ? i : 0u;
        dx[i] = direction[r].x;
        dy[i] = direction[r].y;
        dz[i] = direction[r].z;
    }
    const float8 x = vload8(0, dx), y = vload8(0, dy), z = vload8(0, dz);
    /* box_ray's reciprocals, whose signs must be lane 0's on every axis. */
    const float flt_max = 0x1.fffffep127f;
    p->box.inv_x = max(min(1.0f / x, flt_max), -flt_max);
    p->box.inv_y = max(min(1.0f / y, flt_max), -flt_max);
    p->box.inv_z = max(min(1.0f / z, flt_max), -flt_max);
    const uint32_t all = (1u << WF_PACKET_RAYS) - 1u;
    if (lane_bits8(isless(p->box.inv_x, 0.0f)) != (first.near_row[0] ? all : 0u) ||
        lane_bits8(isless(p->box.inv_y, 0.0f)) != (first.near_row[1] & 1 ? all : 0u) ||
        lane_bits8(isless(p->box.inv_z, 0.0f)) != (first.near_row[2] & 1 ? all : 0u))
        return 0;
    /* watertight_ray's axis of the largest |component|, lane 0's in every lane. */
    p->first = watertight_ray(origin[0], direction[0]);
    const float8 ax = fabs(x), ay = fabs(y), az = fabs(z);
    const int8 is_x = isgreaterequal(ax, ay) & isgreaterequal(ax, az);
    const int8 is_y = ~is_x & isgreaterequal(ay, az);
    const int8 kz = p->first.kz == 0 ? is_x : (p->first.kz == 1 ? is_y : ~is_x & ~is_y);
    if (lane_bits8(kz) != all) return 0;
    const float8 d_kz = packet_row(x, y, z, p->first.kz);
    vstore8(packet_row(x, y, z, p->first.kx) / d_kz, 0, p->shear_x);
    vstore8(packet_row(x, y, z, p->first.ky) / d_kz, 0, p->shear_y);
    vstore8(1.0f / d_kz, 0, p->scale_z);
    p->ray.origin.x = (float8)(p->first.origin.x);
    p->ray.origin.y = (float8)(p->first.origin.y);
    p->ray.origin.z = (float8)(p->first.origin.z);
    p->ray.shear_x = vload8(0, p->shear_x);
    p->ray.shear_y = vload8(0, p->shear_y);
    p->ray.scale_z = vload8(0, p->scale_z);
    p->ray.kx = p->first.kx;
    p->ray.ky = p->first.ky;
    p->ray.kz = p->first.kz;
    p->box.near_origin = first.near_origin; /* one origin: every lane's */
    p->box.far_origin = first.far_origin;
    p->box.inv_lo = make_float3(min_lane(p->box.inv_x), min_lane(p->box.inv_y), min_lane(p->box.inv_z));
    p->box.inv_hi = make_float3(max_lane(p->box.inv_x), max_lane(p->box.inv_y), max_lane(p->box.inv_z));
    for (int a = 0; a < 3; ++a) p->box.near_row[a] = first.near_row[a];
    p->lanes = (1u << count) - 1u;
    return 1;
}

/* The least distance over the lanes to planes `row` of the node's slots, or
 * (far) the greatest, on one axis. */
WF_FORCE_INLINE float8 packet_plane_distance(WF_GLOBAL const BvhNode* node, int row, float origin, float inv_lo,
                                             float inv_hi, int far) {
    const float8 d = vload8(0, node->bounds[row]) - origin;
    return far ? max(d * inv_lo, d * inv_hi) : min(d * inv_lo, d * inv_hi);
}

/* The children whose box some lane may meet before t_limit, the greatest
 * window end of the lanes, as bit i for slot i, and in entry[i] the least
 * entry of the lanes into slot i's box. */
WF_FORCE_INLINE uint32_t packet_children(const PacketBox* b, WF_GLOBAL const BvhNode* node, float t_limit,
                                         float* entry) {
    const float8 near_x = packet_plane_distance(node, b->near_row[0], b->near_origin.x, b->inv_lo.x, b->inv_hi.x, 0);
    const float8 near_y = packet_plane_distance(node, b->near_row[1], b->near_origin.y, b->inv_lo.y, b->inv_hi.y, 0);
    const float8 near_z = packet_plane_distance(node, b->near_row[2], b->near_origin.z, b->inv_lo.z, b->inv_hi.z, 0);
    const float8 far_x = packet_plane_distance(node, b->near_row[0] ^ 1, b->far_origin.x, b->inv_lo.x, b->inv_hi.x, 1);
    const float8 far_y = packet_plane_distance(node, b->near_row[1] ^ 1, b->far_origin.y, b->inv_lo.y, b->inv_hi.y, 1);
    const float8 far_z = packet_plane_distance(node, b->near_row[2] ^ 1, b->far_origin.z, b->inv_lo.z, b->inv_hi.z, 1);
    const float8 enter = max(max(near_x, near_y), max(near_z, 0.0f));
    const float8 exit = min(min(far_x, far_y), min(far_z, t_limit)) * (1.0f + 0x1p-21f);
    vstore8(enter, 0, entry);
    return lane_bits8(islessequal(enter, exit));
}

/* The lanes whose ray meets slot `slot`'s box before its own window end:
 * each lane's child_entries, to the bit. */
WF_FORCE_INLINE uint32_t packet_lanes_meeting(const PacketBox* b, WF_GLOBAL const BvhNode* node, uint32_t slot,
                                              float8 window) {
    const float8 near_x = (node->bounds[b->near_row[0]][slot] - b->near_origin.x) * b->inv_x;
    const float8 near_y = (node->bounds[b->near_row[1]][slot] - b->near_origin.y) * b->inv_y;
    const float8 near_z = (node->bounds[b->near_row[2]][slot] - b->near_origin.z) * b->inv_z;
    const float8 far_x = (node->bounds[b->near_row[0] ^ 1][slot] - b->far_origin.x) * b->inv_x;
    const float8 far_y = (node->bounds[b->near_row[1] ^ 1][slot] - b->far_origin.y) * b->inv_y;
    const float8 far_z = (node->bounds[b->near_row[2] ^ 1][slot] - b->far_origin.z) * b->inv_z;
    const float8 enter = max(max(near_x, near_y), max(near_z, 0.0f));
    const float8 exit = min(min(far_x, far_y), min(far_z, window)) * (1.0f + 0x1p-21f);
    return lane_bits8(islessequal(enter, exit));
}

/* Triangle `lane` of block `b`, the same in every lane, permuted for the packet. */
WF_FORCE_INLINE TriangleLanes_x8 packet_triangle(const PacketRay* ray, WF_GLOBAL const TriangleBlock* b,
                                                 uint32_t lane) {
    TriangleLanes_x8 one;
    one.v0.x = (float8)(b->corners[ray->kx][lane]);
    one.v0.y = (float8)(b->corners[ray->ky][lane]);
    one.v0.z = (float8)(b->corners[ray->kz][lane]);
    one.v1.x = (float8)(b->corners[3 + ray->kx][lane]);
    one.v1.y = (float8)(b->corners[3 + ray->ky][lane]);
    one.v1.z = (float8)(b->corners[3 + ray->kz][lane]);
    one.v2.x = (float8)(b->corners[6 + ray->kx][lane]);
    one.v2.y = (float8)(b->corners[6 + ray->ky][lane]);
    one.v2.z = (float8)(b->corners[6 + ray->kz][lane]);
    return one;
}

/* Lanes fewer than this test a leaf one ray at a time, four triangles in
 * each test, where the packet's test takes one triangle at a time: the two
 * cost the same at four lanes of a leaf of four. */
#define WF_PACKET_LEAF_LANES 4

/* The closest hit in (0, t_max) of each of the packet's rays, into hit[0 .. count). */
WF_INLINE void bvh_closest_hits_packet(WF_GLOBAL const BvhNode* nodes, WF_GLOBAL const TriangleBlock* triangles,
                                       const Packet* p, uint32_t count, float t_max WF_TRAVERSAL_SCENE_PARAM,
                                       RayHit* hit) {
    HitSelection selection[WF_PACKET_RAYS];
    float window[WF_PACKET_RAYS]; /* selection[i].window_end, side by side for the lanes' loads */
    for (int i = 0; i < WF_PACKET_RAYS; ++i) {
        selection[i] = no_hits(t_max);
        window[i] = t_max;
    }
    float window_max = t_max; /* the greatest of window[] */
    uint32_t stack_child[WF_BVH_STACK_SIZE];
    float stack_entry[WF_BVH_STACK_SIZE];
    uchar stack_lanes[WF_BVH_STACK_SIZE];
    int stack_size = 0;
    uint32_t child = nodes->child[0], lanes = p->lanes;
    for (;;) {
        if (child & WF_BVH_LEAF) {
            const uint32_t first = child & WF_BVH_FIRST_MASK;
            const uint32_t end = first + ((child & ~WF_BVH_LEAF) >> WF_BVH_COUNT_SHIFT) + 1u;
            int found_any = 0;
            if (popcount(lanes) >= WF_PACKET_LEAF_LANES) {
                for (uint32_t position = first; position < end; ++position) {
                    WF_GLOBAL const TriangleBlock* b = triangles + position / WF_BLOCK_LANES;
                    const uint32_t lane = position % WF_BLOCK_LANES;
                    const TriangleLanes_x8 one = packet_triangle(&p->ray, b, lane);
                    TriangleHit hits[WF_PACKET_RAYS];
                    uint32_t found =
                        intersect_triangles_x8(&p->ray, &one, lanes, (float8)(t_max), vload8(0, window), hits);
                    for (; found != 0u; found &= found - 1u) {
                        const uint32_t r = lowest_bit(found);
                        if (!WF_HIT_PASSES(triangles, (int32_t)position, &hits[r])) continue;
                        select_hit(&selection[r], &hits[r], (int32_t)position, -1, b->light[lane] >= 0);
                        window[r] = selection[r].window_end;
                        found_any = 1;
                    }
                }
            } else {
                for (uint32_t m = lanes; m != 0u; m &= m - 1u) {
                    const uint32_t r = lowest_bit(m);
                    const WatertightRay ray = packet_lane_ray(p, r);
                    leaf_hits(&ray, triangles, first, end, -1, t_max, &selection[r], 0 WF_TRAVERSAL_SCENE_ARG);
                    window[r] = selection[r].window_end;
                }
                found_any = 1;
            }
            if (found_any) window_max = max_lane(vload8(0, window));
        } else {
            WF_GLOBAL const BvhNode* node = nodes + child;
            float entry[WF_BVH_WIDTH];
            const float8 w = vload8(0, window);
            uint32_t met = packet_children(&p->box, node, window_max, entry);
            /* Each met child with the lanes that meet it; none, and it is dropped. */
            uint32_t child_lanes[WF_BVH_WIDTH];
            for (uint32_t m = met; m != 0u; m &= m - 1u) {
                const uint32_t slot = lowest_bit(m);
                child_lanes[slot] = packet_lanes_meeting(&p->box, node, slot, w) & lanes;
                if (child_lanes[slot] == 0u) met &= ~(1u << slot);
            }
            if (met != 0u) { /* on to the nearest, the others pushed */
                uint32_t next = lowest_bit(met);
                for (uint32_t m = met & (met - 1u); m != 0u; m &= m - 1u) {
                    const uint32_t slot = lowest_bit(m);
                    if (entry[slot] < entry[next]) next = slot;
                }
                for (uint32_t m = met & ~(1u << next); m != 0u; m &= m - 1u) {
                    const uint32_t slot = lowest_bit(m);
                    stack_entry[stack_size] = entry[slot];
                    stack_child[stack_size] = node->child[slot];
                    stack_lanes[stack_size] = (uchar)child_lanes[slot];
                    prefetch_child(nodes, triangles, stack_child[stack_size]);
                    ++stack_size;
                }
                child = node->child[next];
                lanes = child_lanes[next];
                continue;
            }
        }
        /* The next pending child, unless every lane's window has since
         * closed before its least entry (see above). */
        do {
            if (stack_size == 0) {
                for (uint32_t i = 0; i < count; ++i) hit[i] = selected_hit(&selection[i]);
                return;
            }
            --stack_size;
        } while (stack_entry[stack_size] > window_max * (1.0f + 0x1p-21f));
        child = stack_child[stack_size];
        lanes = stack_lanes[stack_size];
    }
}
#endif

#endif /* WF_BVH_PACKET_H */
