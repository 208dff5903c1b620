/* instance_map.h — a placement's affine maps (Instance, include/wavefront/scene_types.h)
 * applied to points and vectors: the ray taken into a shared mesh's space
 * (geometry/bvh_traverse.h) and its hit brought back to the world
 * (stages/shade.h), with the bound of the rounding a point picks up on the
 * way. Shared by the kernels and the host. */
#ifndef WF_INSTANCE_MAP_H
#define WF_INSTANCE_MAP_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"
#include "geometry/float_error.h"

WF_DEVICE_BEGIN

/* m (rows of a 3x4 matrix) times the point p: linear part and translation. */
WF_INLINE float3 map_point(WF_GLOBAL const float (*m)[4], float3 p) {
    return make_float3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                       m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                       m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
}

/* m's linear part times v. */
WF_INLINE float3 map_vector(WF_GLOBAL const float (*m)[4], float3 v) {
    return make_float3(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                       m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
}

/* The transpose of m's linear part times n: a normal taken by the inverse
 * transpose of the map whose inverse m is (world_to_object for a normal
 * going to the world), up to its length. */
WF_INLINE float3 map_normal(WF_GLOBAL const float (*m)[4], float3 n) {
    return make_float3(m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z, m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
                       m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z);
}

/* The error bound of map_point(m, p) for a p known within +-error, per
 * component (pbrt-v4's Transform of a Point3fi): the error carried through
 * the linear part, and the rounding of the three products and three sums,
 * gamma_3 of the terms' magnitudes, times `scale` (Instance.error_scale,
 * host/bvh/instance_bvh.cpp): enough that a ray leaving the point along a
 * bound this wide stays clear of the surface once it is mapped into the
 * mesh's space again (bvh_traverse.h), that map's rounding and the stored
 * inverse's included; 0 for the identity, whose maps are exact. The carried
 * error needs no such factor: mapped back, a world offset of |M| error along
 * the normal clears the mesh's own bound. */
WF_INLINE float3 map_point_error(WF_GLOBAL const float (*m)[4], float3 p, float3 error, float scale) {
    const float g3 = rounding_gamma(3);
    float e[3];
    for (int r = 0; r < 3; ++r) {
        const float terms = fabs(m[r][0] * p.x) + fabs(m[r][1] * p.y) + fabs(m[r][2] * p.z) + fabs(m[r][3]);
        const float carried = fabs(m[r][0]) * error.x + fabs(m[r][1]) * error.y + fabs(m[r][2]) * error.z;
        e[r] = (1.0f + g3) * carried + scale * g3 * terms;
    }
    return make_float3(e[0], e[1], e[2]);
}

WF_DEVICE_END

#endif /* WF_INSTANCE_MAP_H */
