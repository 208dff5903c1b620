/* valid_reflection.h — keeps a bent shading normal from mirroring the view
 * below the surface; shared by the kernels and the host.
 *
 * A normal map may tilt the shading normal n so far from the geometric normal
 * ng that the mirror direction of the view, r = 2 (n.v) n - v, points into
 * the surface: a smooth metal then reflects nothing there and shows black
 * rings. As Cycles does (ensure_valid_reflection), such an n is replaced by
 * the normal whose mirror direction lies just above the surface: r is lifted
 * within its plane with ng until r.ng = min(0.9 v.ng, 0.01), and n becomes
 * the half vector of v and that r. A normal whose reflection is already above
 * that height is returned as it is. All vectors unit; v points away from the
 * surface, on ng's side. */
#ifndef WF_VALID_REFLECTION_H
#define WF_VALID_REFLECTION_H

#include "wavefront/compat.h"

WF_DEVICE_BEGIN

WF_INLINE float3 valid_reflection_normal(float3 ng, float3 v, float3 n) {
    const float3 r = 2.0f * dot(n, v) * n - v;
    const float height = min(0.9f * dot(v, ng), 0.01f);
    if (dot(r, ng) >= height) return n;
    /* r's direction along the surface; where it has none, the view's opposite. */
    float3 along = r - dot(r, ng) * ng;
    float len = sqrt(dot(along, along));
    if (!(len > 1e-6f)) {
        along = dot(v, ng) * ng - v;
        len = sqrt(dot(along, along));
        if (!(len > 1e-6f)) return ng;
    }
    const float3 lifted = sqrt(max(0.0f, 1.0f - height * height)) * (along / len) + height * ng;
    const float3 h = v + lifted;
    const float h_len = sqrt(dot(h, h));
    return h_len > 0.0f ? h / h_len : ng;
}

WF_DEVICE_END

#endif /* WF_VALID_REFLECTION_H */
