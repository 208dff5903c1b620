/* sampling.h — the warps from uniform numbers to directions and points, each
 * with the density it produces; shared by the kernels and the host (the BSDF
 * tests run bsdf/bsdf.h, which samples with these, on the host). */
#ifndef WF_SAMPLING_H
#define WF_SAMPLING_H

#include "wavefront/compat.h"

#define WF_PI 3.14159265358979323846f
#define WF_INV_PI 0.31830988618379067154f

WF_DEVICE_BEGIN

/* An orthonormal basis around the unit vector n (Duff et al., "Building an
 * Orthonormal Basis, Revisited", JCGT 2017): no branch on a preferred axis,
 * continuous except at n.z = -0. The host's (the ray bench); shade's frame is
 * stages/surface.inc's lane form of the same arithmetic. */
WF_INLINE void orthonormal_basis(float3 n, float3* t, float3* b) {
    const float sign = copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    *t = make_float3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = make_float3(c, sign + n.y * n.y * a, -n.y);
}

/* Concentric map of the unit square onto the unit disk (Shirley and Chiu 1997). */
WF_INLINE float2 sample_disk_concentric(float2 u) {
    const float2 o = 2.0f * u - 1.0f;
    if (o.x == 0.0f && o.y == 0.0f) return make_float2(0.0f, 0.0f);
    float r, theta; /* in units of pi */
    if (fabs(o.x) > fabs(o.y)) {
        r = o.x;
        theta = 0.25f * (o.y / o.x);
    } else {
        r = o.y;
        theta = 0.5f - 0.25f * (o.x / o.y);
    }
    return r * make_float2(cospi(theta), sinpi(theta));
}

/* A direction about +z with density cos(theta) / pi (Malley's method). */
WF_INLINE float3 sample_cosine_hemisphere(float2 u) {
    const float2 d = sample_disk_concentric(u);
    const float z = sqrt(max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return make_float3(d.x, d.y, z);
}

/* A direction about +z with density 1 / 2pi. */
WF_INLINE float3 sample_uniform_hemisphere(float2 u) {
    const float z = u.x;
    const float r = sqrt(max(0.0f, 1.0f - z * z));
    return make_float3(r * cospi(2.0f * u.y), r * sinpi(2.0f * u.y), z);
}

/* Barycentrics (b1, b2) of a point uniform in area on a triangle. */
WF_INLINE float2 sample_triangle_uniform(float2 u) {
    const float su = sqrt(u.x);
    return make_float2(1.0f - su, u.y * su);
}

/* Veach's power heuristic with beta = 2, for one sample from each technique.
 * Written as 1 / (1 + (other/this)^2) so that a pdf whose square overflows (a
 * light of area 1e-16 has a solid-angle pdf near 1e19) still gives the right
 * limit instead of Inf/Inf = NaN. */
WF_INLINE float power_heuristic(float pdf_this, float pdf_other) {
    if (!(pdf_this > 0.0f)) return 0.0f;
    const float ratio = pdf_other / pdf_this;
    return 1.0f / (1.0f + ratio * ratio);
}

WF_DEVICE_END

#endif
