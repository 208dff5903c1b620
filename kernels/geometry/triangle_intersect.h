/* triangle_intersect.h — the watertight ray/triangle test of Woop, Benthin and
 * Wald ("Watertight Ray/Triangle Intersection", JCGT 2013), shared by the
 * kernels and the host.
 *
 * Promises: a ray through an edge or a vertex shared by triangles of a closed
 * mesh hits at least one of them (no cracks), whatever the rounding. Both faces
 * count (no culling). A hit comes with t, a bound t_error such that the exact
 * t at which the ray meets the triangle's plane lies within t_error of t, and
 * barycentrics u, v with p = (1 - u - v) v0 + u v1 + v v2. It is reported
 * only when that exact t is surely inside (0, t_max): t - t_error > 0 and
 * t + t_error < t_max. So a plane through or behind the origin is never hit,
 * and a ray from a point offset by geometry/ray_offset.h does not find the
 * surface it leaves; nor is a plane at or beyond t_max, and a shadow segment
 * that ends just short of a light does not find the light. A zero-area
 * triangle is hit only by a ray that passes through it within rounding error.
 * Precondition: the direction is finite and not zero; it need not be unit.
 *
 * How: each ray gets a transform that moves its origin to 0, permutes the axes
 * so that the direction's largest component becomes z, and shears the
 * direction onto +z. Every vertex is transformed by the same arithmetic, so
 * triangles that share an edge see identical 2D endpoints, and their edge
 * functions for it are exact negatives of each other: the sign tests agree.
 * An edge function that rounds to exactly 0 is recomputed in double, where the
 * products of floats are exact, so its sign is the true one.
 *
 * Four triangles are tested at once, one per float4 lane, as a block of the
 * BVH's triangles holds them; intersect_triangle is lane 0 of the same test, so one
 * triangle alone gets the very bits it gets in a leaf. A GPU's traversal tests
 * one at a time (geometry/triangle_lanes.inc, where the test is written once
 * for both widths), with the same bits again. Every lane goes
 * through the scalar operations the formulas below name, in their order. The
 * permutation is applied as the corners are loaded into lanes (x lanes hold
 * each corner's kx component, and so on: a block's row for that axis), so the
 * shear is two operations per coordinate.
 *
 * The device compiler may not contract a * b + c into fused multiply-adds in
 * these functions (WF_FP_CONTRACT_OFF): every vertex must go through the same
 * roundings and shared edge functions must stay exact negatives. So the host
 * (GCC in ISO C++ mode does not contract either) and a device whose division
 * is correctly rounded, such as PoCL, compute the same bits.
 *
 * The bound on t follows Pharr, Jakob and Humphreys (Physically Based
 * Rendering, 4th ed., section 6.8), redone for this transform so that it
 * does not grow with the distance to a triangle seen face-on. gamma_n is as in
 * geometry/float_error.h; capitals are exact values, lower case computed ones.
 *  - x = fl(a_kx - fl(s a_kz)), with a = fl(v - origin) and s = fl(d_kx / d_kz),
 *    is within gamma_6 dot(|shear_x|, |a|) of X; y likewise. dx, dy: the
 *    largest over the vertices, widened to gamma_8 for their own dot product.
 *  - z = fl(fl(1 / d_kz) a_kz) is within gamma_3 |Z| <= gamma_4 |z|: dz = gamma_4 max|z|.
 *  - e = fl(fl(px qy) - fl(py qx)) is within de = 2 (gamma_2 mx my + mx dy +
 *    my dx + dx dy) of E, mx and my the largest |x| and |y|; the double
 *    retest is closer still.
 *  - The e of a hit share one sign, so sum|e| <= |det| (1 + gamma_2), and
 *    det = fl(sum e) and N = fl(sum e z) round by gamma_2 and gamma_3.
 * Writing sum E Z = T sum E and splitting e z - E Z, the exact T satisfies
 *   N / det - T = (sum (e - E)(Z - T) + sum e (z - Z) + rounding of N
 *                  - T rounding of det) / det,
 * in which |Z - T| <= dz + w + |T - t|, w = max|z - t|. With t = fl(N fl(1 /
 * det)) within gamma_3 |t| of N / det and q = 3 de / |det|, solving for
 * |T - t| gives
 *   t_error = (gamma_7 |t| + gamma_9 max|z| + q (w + dz)) / (1 - q - gamma_4),
 * times 1 + gamma_12 for the dozen roundings of this sum itself. The spread w,
 * not the distance max|z|, multiplies q, the large factor for small or
 * distant triangles, so the bound stays a few ulps of t for a triangle seen
 * face-on. Where q + gamma_4 >= 1 rounding may even have flipped det's sign:
 * no bound, and no hit. */
#ifndef WF_TRIANGLE_INTERSECT_H
#define WF_TRIANGLE_INTERSECT_H

#include "wavefront/compat.h"
#include "geometry/float_error.h"

/* Edge functions that round to 0 are redone in double wherever double exists. */
#ifdef __OPENCL_C_VERSION__
#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#define WF_EDGE_FUNCTION_DOUBLE_FALLBACK 1
#endif
#else
#define WF_EDGE_FUNCTION_DOUBLE_FALLBACK 1
#endif

#ifdef __OPENCL_C_VERSION__
#define WF_FP_CONTRACT_OFF _Pragma("OPENCL FP_CONTRACT OFF")
#else
#define WF_FP_CONTRACT_OFF
#endif

WF_DEVICE_BEGIN

/* A ray prepared for many triangle tests: corner p maps to
 * (p_kx - o_kx - shear_x (p_kz - o_kz), p_ky - o_ky - shear_y (p_kz - o_kz),
 * scale_z (p_kz - o_kz)), which puts the ray on the +z axis with z measured in
 * units of t. */
typedef struct WatertightRay {
    float3 origin;  /* permuted as the corners are: (o_kx, o_ky, o_kz) */
    float shear_x;  /* d_kx / d_kz */
    float shear_y;  /* d_ky / d_kz */
    float scale_z;  /* 1 / d_kz */
    int kx, ky, kz; /* kz is the axis of the direction's largest |component| */
} WatertightRay;

typedef struct TriangleHit {
    float t;
    float t_error; /* the exact t lies within t_error of t */
    float u;       /* weight of v1 */
    float v;       /* weight of v2 */
} TriangleHit;

WF_INLINE float component(float3 v, int k) { return k == 0 ? v.x : (k == 1 ? v.y : v.z); }

WF_INLINE WatertightRay watertight_ray(float3 origin, float3 direction) {
    WF_FP_CONTRACT_OFF
    const float3 a = fabs(direction);
    WatertightRay ray;
    ray.kz = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    ray.kx = ray.kz == 2 ? 0 : ray.kz + 1;
    ray.ky = ray.kx == 2 ? 0 : ray.kx + 1;
    /* Nonzero, being the largest |component|; |shear| <= 1 and never NaN. */
    const float dz = component(direction, ray.kz);
    ray.origin = make_float3(component(origin, ray.kx), component(origin, ray.ky), component(origin, ray.kz));
    ray.shear_x = component(direction, ray.kx) / dz;
    ray.shear_y = component(direction, ray.ky) / dz;
    ray.scale_z = 1.0f / dz;
    return ray;
}

#ifdef WF_EDGE_FUNCTION_DOUBLE_FALLBACK
WF_INLINE float edge_function_exact_sign(float px, float py, float qx, float qy) {
    /* The products of floats are exact in double: one rounding, right sign. */
    return (float)((double)px * (double)qy - (double)py * (double)qx);
}
#endif

/* The test at four triangles a time (CornerLanes, TriangleLanes,
 * intersect_triangles); in a GPU's traversal at one (..._x1); and in a CPU's
 * packets, eight rays against one triangle (..._x8, geometry/bvh_packet.h). */
#define WF_TW 4
#include "geometry/triangle_lanes.inc"
#undef WF_TW
#if WF_GPU_TRAVERSAL
#define WF_TW 1
#include "geometry/triangle_lanes.inc"
#undef WF_TW
#elif defined(__OPENCL_C_VERSION__)
#define WF_TW 8
#include "geometry/triangle_lanes.inc"
#undef WF_TW
#endif

/* Corner p, permuted for the ray, in every lane. */
WF_INLINE CornerLanes corner_in_every_lane(const WatertightRay* ray, float3 p) {
    const float x = component(p, ray->kx), y = component(p, ray->ky), z = component(p, ray->kz);
    CornerLanes r;
    r.x = make_float4(x, x, x, x);
    r.y = make_float4(y, y, y, y);
    r.z = make_float4(z, z, z, z);
    return r;
}

/* 1 and *hit filled when the ray hits the triangle with its exact t surely in
 * (0, t_max). */
WF_INLINE int intersect_triangle(const WatertightRay* ray, float3 v0, float3 v1, float3 v2, float t_max,
                                 TriangleHit* hit) {
    TriangleLanes one;
    one.v0 = corner_in_every_lane(ray, v0);
    one.v1 = corner_in_every_lane(ray, v1);
    one.v2 = corner_in_every_lane(ray, v2);
    TriangleHit hits[4];
    if (!intersect_triangles(ray, &one, 1u, t_max, t_max, hits)) return 0;
    *hit = hits[0];
    return 1;
}

WF_DEVICE_END

#endif /* WF_TRIANGLE_INTERSECT_H */
