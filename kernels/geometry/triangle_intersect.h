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
 * OpenCL C cannot index a vector by a runtime value, so the permutation is
 * applied as dot products with unit basis vectors; multiplying by 1 and 0 is
 * exact, so this changes nothing about the rounding.
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

/* A ray prepared for many triangle tests: vertex p maps to
 * (dot(shear_x, p - origin), dot(shear_y, p - origin), dot(scale_z, p - origin)),
 * which puts the ray on the +z axis with z measured in units of t. */
typedef struct WatertightRay {
    float3 origin;
    float3 shear_x;
    float3 shear_y;
    float3 scale_z;
} WatertightRay;

typedef struct TriangleHit {
    float t;
    float t_error; /* the exact t lies within t_error of t */
    float u;       /* weight of v1 */
    float v;       /* weight of v2 */
} TriangleHit;

WF_INLINE WatertightRay watertight_ray(float3 origin, float3 direction) {
    WF_FP_CONTRACT_OFF
    /* Rows of the permutation (x, y, z) -> (kx, ky, kz), kz the dominant axis. */
    const float3 a = fabs(direction);
    float3 row_x, row_y, row_z;
    if (a.x >= a.y && a.x >= a.z) {
        row_x = make_float3(0.0f, 1.0f, 0.0f);
        row_y = make_float3(0.0f, 0.0f, 1.0f);
        row_z = make_float3(1.0f, 0.0f, 0.0f);
    } else if (a.y >= a.z) {
        row_x = make_float3(0.0f, 0.0f, 1.0f);
        row_y = make_float3(1.0f, 0.0f, 0.0f);
        row_z = make_float3(0.0f, 1.0f, 0.0f);
    } else {
        row_x = make_float3(1.0f, 0.0f, 0.0f);
        row_y = make_float3(0.0f, 1.0f, 0.0f);
        row_z = make_float3(0.0f, 0.0f, 1.0f);
    }
    /* Nonzero, being the largest |component|; |shear| <= 1 and never NaN. */
    const float dz = dot(row_z, direction);
    WatertightRay ray;
    ray.origin = origin;
    ray.shear_x = row_x - (dot(row_x, direction) / dz) * row_z;
    ray.shear_y = row_y - (dot(row_y, direction) / dz) * row_z;
    ray.scale_z = (1.0f / dz) * row_z;
    return ray;
}

/* Twice the signed area of the 2D triangle (0, p, q); swapping p and q negates
 * it exactly. */
WF_INLINE float edge_function(float px, float py, float qx, float qy) {
    WF_FP_CONTRACT_OFF
    return px * qy - py * qx;
}

#ifdef WF_EDGE_FUNCTION_DOUBLE_FALLBACK
WF_INLINE float edge_function_exact_sign(float px, float py, float qx, float qy) {
    /* The products of floats are exact in double: one rounding, right sign. */
    return (float)((double)px * (double)qy - (double)py * (double)qx);
}
#endif

WF_INLINE float max_component(float3 v) { return max(max(v.x, v.y), v.z); }

/* The bound t_error above, given the vertices relative to the origin (a, b,
 * c), their transformed coordinates (one vertex per component), t and 1 / det
 * of a hit; INFINITY where det's sign is in doubt. */
WF_INLINE float t_error_bound(const WatertightRay* ray, float3 a, float3 b, float3 c, float3 x, float3 y, float3 z,
                              float t, float inv_det) {
    WF_FP_CONTRACT_OFF /* the same bits as the host, so both select the same hit */
    const float3 shear_x = fabs(ray->shear_x), shear_y = fabs(ray->shear_y);
    const float3 abs_a = fabs(a), abs_b = fabs(b), abs_c = fabs(c);
    const float dx = rounding_gamma(8) * max(max(dot(shear_x, abs_a), dot(shear_x, abs_b)), dot(shear_x, abs_c));
    const float dy = rounding_gamma(8) * max(max(dot(shear_y, abs_a), dot(shear_y, abs_b)), dot(shear_y, abs_c));
    const float max_x = max_component(fabs(x)), max_y = max_component(fabs(y)), max_z = max_component(fabs(z));
    const float spread = max_component(fabs(z - t));
    const float dz = rounding_gamma(4) * max_z;
    const float de = 2.0f * (rounding_gamma(2) * max_x * max_y + max_x * dy + max_y * dx + dx * dy);
    const float q = 3.0f * de * fabs(inv_det);
    const float denominator = 1.0f - q - rounding_gamma(4);
    if (!(denominator > 0.0f)) return INFINITY;
    return (rounding_gamma(7) * fabs(t) + rounding_gamma(9) * max_z + q * (spread + dz)) / denominator *
           (1.0f + rounding_gamma(12));
}

/* 1 and *hit filled when the ray hits the triangle with its exact t surely in
 * (0, t_max). */
WF_INLINE int intersect_triangle(const WatertightRay* ray, float3 v0, float3 v1, float3 v2, float t_max,
                                 TriangleHit* hit) {
    WF_FP_CONTRACT_OFF
    const float3 a = v0 - ray->origin;
    const float3 b = v1 - ray->origin;
    const float3 c = v2 - ray->origin;
    const float ax = dot(ray->shear_x, a), ay = dot(ray->shear_y, a);
    const float bx = dot(ray->shear_x, b), by = dot(ray->shear_y, b);
    const float cx = dot(ray->shear_x, c), cy = dot(ray->shear_y, c);

    /* e0 is the weight of v0 (the edge v1 v2), e1 of v1, e2 of v2. */
    float e0 = edge_function(cx, cy, bx, by);
    float e1 = edge_function(ax, ay, cx, cy);
    float e2 = edge_function(bx, by, ax, ay);
#ifdef WF_EDGE_FUNCTION_DOUBLE_FALLBACK
    if ((e0 == 0.0f) | (e1 == 0.0f) | (e2 == 0.0f)) {
        e0 = edge_function_exact_sign(cx, cy, bx, by);
        e1 = edge_function_exact_sign(ax, ay, cx, cy);
        e2 = edge_function_exact_sign(bx, by, ax, ay);
    }
#endif
    /* Mixed signs: a miss. Bitwise, not short-circuit: one well-predicted
     * branch instead of six. */
    const int any_negative = (e0 < 0.0f) | (e1 < 0.0f) | (e2 < 0.0f);
    const int any_positive = (e0 > 0.0f) | (e1 > 0.0f) | (e2 > 0.0f);
    if (any_negative & any_positive) return 0;
    const float det = e0 + e1 + e2;
    if (det == 0.0f) return 0;

    const float az = dot(ray->scale_z, a), bz = dot(ray->scale_z, b), cz = dot(ray->scale_z, c);
    const float scaled_t = e0 * az + e1 * bz + e2 * cz;
    const float inv_det = 1.0f / det;
    const float t = scaled_t * inv_det;
    if (!(t > 0.0f && t < t_max)) return 0; /* the bound below only narrows this */
    /* Rounding can put t above 0 for a plane through or behind the origin, as
     * for the surface a ray has just left, and below t_max for one at or
     * beyond the end of a shadow segment. */
    const float t_error = t_error_bound(ray, a, b, c, make_float3(ax, bx, cx), make_float3(ay, by, cy),
                                        make_float3(az, bz, cz), t, inv_det);
    if (!(t > t_error && t + t_error < t_max)) return 0;
    hit->t = t;
    hit->t_error = t_error;
    hit->u = e1 * inv_det;
    hit->v = e2 * inv_det;
    return 1;
}

WF_DEVICE_END

#endif /* WF_TRIANGLE_INTERSECT_H */
