/* microfacet.h — the isotropic GGX (Trowbridge-Reitz) microfacet distribution
 * in the local shading frame (z = the shading normal); shared by the kernels
 * and the host.
 *
 * alpha is glTF's roughness squared. Directions are unit; w and -w see the
 * same surface (Lambda depends on w.z only through tan^2), so a direction
 * from inside may be passed as it is. Microfacet normals wm have wm.z > 0.
 *
 *  - ggx_d: the distribution of normals, D(wm) = 1 / (pi a^2 (z^2 + s^2/a^2)^2)
 *    with s^2 = x^2 + y^2: the tan^4-free form stays finite at any alpha > 0.
 *  - ggx_lambda, ggx_g1, ggx_g2: Smith's masking, with the height-correlated
 *    masking-shadowing G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014).
 *    A grazing w (w.z = 0) is fully masked: G1 = 0.
 *  - ggx_sample_visible: a normal from the distribution of normals visible from
 *    w (w.z > 0), D_w(wm) = G1(w) max(0, w.wm) D(wm) / w.z (Heitz 2018,
 *    "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)), whose
 *    density ggx_pdf_visible returns. */
#ifndef WF_MICROFACET_H
#define WF_MICROFACET_H

#include "wavefront/compat.h"
#include "common/sampling.h"

WF_DEVICE_BEGIN

WF_INLINE float ggx_d(float3 wm, float alpha) {
    if (wm.z <= 0.0f) return 0.0f;
    const float a2 = alpha * alpha;
    const float t = wm.z * wm.z + (wm.x * wm.x + wm.y * wm.y) / a2;
    return 1.0f / (WF_PI * a2 * t * t);
}

/* Lambda = (sqrt(1 + a^2 tan^2) - 1) / 2, written without the cancellation. */
WF_INLINE float ggx_lambda(float3 w, float alpha) {
    if (w.z == 0.0f) return 1e30f;
    const float a2t2 = alpha * alpha * (w.x * w.x + w.y * w.y) / (w.z * w.z);
    return 0.5f * a2t2 / (1.0f + sqrt(1.0f + a2t2));
}

WF_INLINE float ggx_g1(float3 w, float alpha) { return 1.0f / (1.0f + ggx_lambda(w, alpha)); }

WF_INLINE float ggx_g2(float3 wo, float3 wi, float alpha) {
    return 1.0f / (1.0f + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
}

/* D_w(wm) for w on either side: w is seen from the side it lies on. */
WF_INLINE float ggx_pdf_visible(float3 w, float3 wm, float alpha) {
    const float cos_w = fabs(w.z);
    if (cos_w == 0.0f) return 0.0f;
    const float cos_wm = w.z > 0.0f ? dot(w, wm) : -dot(w, wm);
    return ggx_g1(w, alpha) * max(0.0f, cos_wm) * ggx_d(wm, alpha) / cos_w;
}

/* w.z > 0; u uniform in [0,1)^2. */
WF_INLINE float3 ggx_sample_visible(float3 w, float alpha, float2 u) {
    /* The view direction in the hemisphere configuration (alpha = 1). */
    const float3 vh = normalize(make_float3(alpha * w.x, alpha * w.y, w.z));
    const float len2 = vh.x * vh.x + vh.y * vh.y;
    const float3 t1 = len2 > 0.0f ? make_float3(-vh.y, vh.x, 0.0f) / sqrt(len2) : make_float3(1.0f, 0.0f, 0.0f);
    const float3 t2 = cross(vh, t1);
    /* A point of the disk, squeezed onto the projection of the visible half. */
    const float r = sqrt(u.x);
    const float p1 = r * cospi(2.0f * u.y);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * r * sinpi(2.0f * u.y);
    const float3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    /* Back to the ellipsoid configuration. */
    return normalize(make_float3(alpha * nh.x, alpha * nh.y, max(1e-6f, nh.z)));
}

WF_DEVICE_END

#endif /* WF_MICROFACET_H */
