/* ray_offset.h — where a ray leaving a surface must start, and where a shadow
 * segment ending on one must stop, so that neither meets that surface again;
 * shared by the kernels and the host.
 *
 * Promises (after Pharr, Jakob and Humphreys, Physically Based Rendering, 4th
 * ed., section 6.8):
 *  - interpolation_error bounds, per component, how far the point that
 *    interpolate_triangle computes lies from a point of the triangle, for
 *    barycentrics b1, b2 >= 0 with b1 + b2 <= 1 (up to rounding).
 *  - offset_ray_origin moves such a point along the geometric normal to the
 *    side that a direction leaves by, past every plane the error box allows,
 *    and then one float further from the surface in every moved coordinate:
 *    the surface's plane lies exactly behind the new origin.
 *  - segment_to_surface ends a segment short of a surface the same way, with
 *    the box grown by the rounding of the segment itself: the exact end of
 *    origin + 1 * segment lies in front of the surface's plane.
 * geometry/triangle_intersect.h reports a hit only where the exact t is
 * surely in (0, t_max), so neither surface is found again, at any angle.
 * No fixed epsilon: every step scales with the coordinates and vanishes with
 * them, so a scene behaves the same at any scale and any translation.
 * The kernels find their hit points with stages/surface.inc's lane form of
 * interpolate_triangle and interpolation_error, and spawn their rays with
 * stages/scatter.inc's of offset_ray_origin and segment_to_surface, the same
 * arithmetic a lane at a time; these serve the host
 * (tests/kernels/test_ray_offset.cpp, the ray bench).
 *
 * Why the bound holds: b0 = 1 - b1 - b2 is computed with an absolute error of
 * at most gamma_2 (1 + b1 + b2), so the float weights sum to 1 + s with
 * |s| <= 4u, to first order. Their exact combination is then (1 + s) times a
 * point q of the triangle, q's weights being the float ones divided by 1 + s;
 * it is off q by |s q| <= 4u sum|b_i p_i|. Evaluating the sum adds at most
 * gamma_3 sum|b_i p_i|. Together: below gamma_7 sum|b_i p_i|, the bound pbrt
 * uses. */
#ifndef WF_RAY_OFFSET_H
#define WF_RAY_OFFSET_H

#include "wavefront/compat.h"
#include "geometry/float_error.h"

WF_DEVICE_BEGIN

/* b0 p0 + b1 p1 + b2 p2, with b0 = 1 - b1 - b2. */
WF_INLINE float3 interpolate_triangle(float3 p0, float3 p1, float3 p2, float b1, float b2) {
    return (1.0f - b1 - b2) * p0 + b1 * p1 + b2 * p2;
}

/* The bound, per component, on interpolate_triangle's distance from the triangle. */
WF_INLINE float3 interpolation_error(float3 p0, float3 p1, float3 p2, float b1, float b2) {
    const float b0 = 1.0f - b1 - b2;
    return rounding_gamma(7) * (fabs(b0 * p0) + fabs(b1 * p1) + fabs(b2 * p2));
}

/* One float beyond `moved`, away from where it was moved from. */
WF_INLINE float round_away(float moved, float step) {
    if (step > 0.0f) return nextafter(moved, INFINITY);
    if (step < 0.0f) return nextafter(moved, -INFINITY);
    return moved;
}

/* p, within p_error of a surface whose unit geometric normal is n, moved off
 * that surface to the side that direction w leaves by. The plane through any
 * point of the error box is at most dot(|n|, p_error) from p along n; the
 * final rounding keeps the sum p + offset from falling back towards it. */
WF_INLINE float3 offset_ray_origin(float3 p, float3 p_error, float3 n, float3 w) {
    const float distance = dot(fabs(n), p_error);
    const float3 offset = (dot(n, w) < 0.0f ? -distance : distance) * n;
    const float3 moved = p + offset;
    return make_float3(round_away(moved.x, offset.x), round_away(moved.y, offset.y),
                       round_away(moved.z, offset.z));
}

/* The segment from origin to p, within p_error of a surface with unit normal n,
 * stopped short of that surface. Its end, origin + segment, is off the end
 * point that was offset by the rounding of the difference, up to u |p - origin|
 * per component; gamma_2 covers that and the offset's own share of it. */
WF_INLINE float3 segment_to_surface(float3 origin, float3 p, float3 p_error, float3 n) {
    const float3 end_error = p_error + rounding_gamma(2) * fabs(p - origin);
    return offset_ray_origin(p, end_error, n, origin - p) - origin;
}

WF_DEVICE_END

#endif /* WF_RAY_OFFSET_H */
