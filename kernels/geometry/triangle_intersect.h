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
 * triangle alone gets the very bits it gets in a leaf. Every lane goes
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

/* One corner of four triangles, a lane each, permuted for the ray: x holds
 * each corner's kx component, y its ky, z its kz. */
typedef struct CornerLanes {
    float4 x, y, z;
} CornerLanes;

typedef struct TriangleLanes {
    CornerLanes v0, v1, v2;
} TriangleLanes;

WF_FORCE_INLINE CornerLanes corner_minus(CornerLanes p, float3 origin) {
    CornerLanes r;
    r.x = p.x - origin.x;
    r.y = p.y - origin.y;
    r.z = p.z - origin.z;
    return r;
}

WF_FORCE_INLINE CornerLanes fabs_lanes(CornerLanes p) {
    CornerLanes r;
    r.x = fabs(p.x);
    r.y = fabs(p.y);
    r.z = fabs(p.z);
    return r;
}

/* Twice the signed area of the 2D triangle (0, p, q); swapping p and q negates
 * it exactly. */
WF_FORCE_INLINE float4 edge_function(float4 px, float4 py, float4 qx, float4 qy) {
    WF_FP_CONTRACT_OFF
    return px * qy - py * qx;
}

#ifdef WF_EDGE_FUNCTION_DOUBLE_FALLBACK
WF_INLINE float edge_function_exact_sign(float px, float py, float qx, float qy) {
    /* The products of floats are exact in double: one rounding, right sign. */
    return (float)((double)px * (double)qy - (double)py * (double)qx);
}

/* The three edge functions of each lane in which one rounded to exactly 0,
 * redone in double. Rare: one lane at a time. */
WF_INLINE void redo_zero_edge_functions(float4 ax, float4 ay, float4 bx, float4 by, float4 cx, float4 cy,
                                        float4* e0, float4* e1, float4* e2) {
    float x[3][4], y[3][4], e[3][4];
    vstore4(ax, 0, x[0]);
    vstore4(bx, 0, x[1]);
    vstore4(cx, 0, x[2]);
    vstore4(ay, 0, y[0]);
    vstore4(by, 0, y[1]);
    vstore4(cy, 0, y[2]);
    vstore4(*e0, 0, e[0]);
    vstore4(*e1, 0, e[1]);
    vstore4(*e2, 0, e[2]);
    for (int i = 0; i < 4; ++i) {
        if (e[0][i] != 0.0f && e[1][i] != 0.0f && e[2][i] != 0.0f) continue;
        e[0][i] = edge_function_exact_sign(x[2][i], y[2][i], x[1][i], y[1][i]);
        e[1][i] = edge_function_exact_sign(x[0][i], y[0][i], x[2][i], y[2][i]);
        e[2][i] = edge_function_exact_sign(x[1][i], y[1][i], x[0][i], y[0][i]);
    }
    *e0 = vload4(0, e[0]);
    *e1 = vload4(0, e[1]);
    *e2 = vload4(0, e[2]);
}
#endif

WF_FORCE_INLINE float4 max3(float4 a, float4 b, float4 c) { return max(max(a, b), c); }

/* The bound t_error above in every lane, given the corners relative to the
 * origin (a, b, c), their transformed coordinates, t and 1 / det; INFINITY
 * where det's sign is in doubt. */
WF_FORCE_INLINE float4 t_error_bound(const WatertightRay* ray, CornerLanes a, CornerLanes b, CornerLanes c,
                                     float4 ax, float4 bx, float4 cx, float4 ay, float4 by, float4 cy,
                                     float4 az, float4 bz, float4 cz, float4 t, float4 inv_det) {
    WF_FP_CONTRACT_OFF /* the same bits as the host, so both select the same hit */
    const float shear_x = fabs(ray->shear_x), shear_y = fabs(ray->shear_y);
    const CornerLanes abs_a = fabs_lanes(a), abs_b = fabs_lanes(b), abs_c = fabs_lanes(c);
    /* dot(|shear row|, |corner|), the row being 1 at kx (or ky), shear at kz, 0 elsewhere. */
    const float4 dx = rounding_gamma(8) * max3(abs_a.x + shear_x * abs_a.z, abs_b.x + shear_x * abs_b.z,
                                               abs_c.x + shear_x * abs_c.z);
    const float4 dy = rounding_gamma(8) * max3(abs_a.y + shear_y * abs_a.z, abs_b.y + shear_y * abs_b.z,
                                               abs_c.y + shear_y * abs_c.z);
    const float4 max_x = max3(fabs(ax), fabs(bx), fabs(cx)), max_y = max3(fabs(ay), fabs(by), fabs(cy));
    const float4 max_z = max3(fabs(az), fabs(bz), fabs(cz));
    const float4 spread = max3(fabs(az - t), fabs(bz - t), fabs(cz - t));
    const float4 dz = rounding_gamma(4) * max_z;
    const float4 de = 2.0f * (rounding_gamma(2) * max_x * max_y + max_x * dy + max_y * dx + dx * dy);
    const float4 q = 3.0f * de * fabs(inv_det);
    const float4 denominator = 1.0f - q - rounding_gamma(4);
    const float4 bound = (rounding_gamma(7) * fabs(t) + rounding_gamma(9) * max_z + q * (spread + dz)) / denominator *
                         (1.0f + rounding_gamma(12));
    const float4 zero = make_float4(0.0f, 0.0f, 0.0f, 0.0f);
    return select(make_float4(INFINITY, INFINITY, INFINITY, INFINITY), bound, isgreater(denominator, zero));
}

/* Of the lanes set in `lanes`, those whose triangle the ray hits with its
 * exact t surely in (0, t_max), as bit i for lane i, with hits[i] filled for
 * each; of those, only the ones whose t is at most t_cull (traversal has no
 * use for the others, and skips the bound for them). */
WF_FORCE_INLINE uint32_t intersect_triangles(const WatertightRay* ray, const TriangleLanes* triangles, uint32_t lanes,
                                             float t_max, float t_cull, TriangleHit* hits) {
    WF_FP_CONTRACT_OFF
    const CornerLanes a = corner_minus(triangles->v0, ray->origin);
    const CornerLanes b = corner_minus(triangles->v1, ray->origin);
    const CornerLanes c = corner_minus(triangles->v2, ray->origin);
    const float4 ax = a.x - ray->shear_x * a.z, ay = a.y - ray->shear_y * a.z;
    const float4 bx = b.x - ray->shear_x * b.z, by = b.y - ray->shear_y * b.z;
    const float4 cx = c.x - ray->shear_x * c.z, cy = c.y - ray->shear_y * c.z;

    /* e0 is the weight of v0 (the edge v1 v2), e1 of v1, e2 of v2. */
    float4 e0 = edge_function(cx, cy, bx, by);
    float4 e1 = edge_function(ax, ay, cx, cy);
    float4 e2 = edge_function(bx, by, ax, ay);
    const float4 zero = make_float4(0.0f, 0.0f, 0.0f, 0.0f);
#ifdef WF_EDGE_FUNCTION_DOUBLE_FALLBACK
    if ((lane_bits4(isequal(e0, zero) | isequal(e1, zero) | isequal(e2, zero)) & lanes) != 0u)
        redo_zero_edge_functions(ax, ay, bx, by, cx, cy, &e0, &e1, &e2);
#endif
    /* Mixed signs: a miss. */
    const int4 any_negative = isless(e0, zero) | isless(e1, zero) | isless(e2, zero);
    const int4 any_positive = isgreater(e0, zero) | isgreater(e1, zero) | isgreater(e2, zero);
    const float4 det = e0 + e1 + e2;
    int4 valid = ~(any_negative & any_positive) & ~isequal(det, zero);
    if ((lane_bits4(valid) & lanes) == 0u) return 0u;

    const float4 az = ray->scale_z * a.z, bz = ray->scale_z * b.z, cz = ray->scale_z * c.z;
    const float4 scaled_t = e0 * az + e1 * bz + e2 * cz;
    const float4 inv_det = 1.0f / det;
    const float4 t = scaled_t * inv_det;
    const float4 limit = make_float4(t_max, t_max, t_max, t_max);
    const float4 cull = make_float4(t_cull, t_cull, t_cull, t_cull);
    /* The bound below only narrows (0, t_max). */
    valid = valid & isgreater(t, zero) & isless(t, limit) & islessequal(t, cull);
    if ((lane_bits4(valid) & lanes) == 0u) return 0u;
    /* Rounding can put t above 0 for a plane through or behind the origin, as
     * for the surface a ray has just left, and below t_max for one at or
     * beyond the end of a shadow segment. */
    const float4 t_error = t_error_bound(ray, a, b, c, ax, bx, cx, ay, by, cy, az, bz, cz, t, inv_det);
    const uint32_t bits = lane_bits4(valid & isgreater(t, t_error) & isless(t + t_error, limit)) & lanes;
    if (bits == 0u) return 0u;
    float lane_t[4], lane_error[4], lane_u[4], lane_v[4];
    vstore4(t, 0, lane_t);
    vstore4(t_error, 0, lane_error);
    vstore4(e1 * inv_det, 0, lane_u);
    vstore4(e2 * inv_det, 0, lane_v);
    for (int i = 0; i < 4; ++i) {
        hits[i].t = lane_t[i];
        hits[i].t_error = lane_error[i];
        hits[i].u = lane_u[i];
        hits[i].v = lane_v[i];
    }
    return bits;
}

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
