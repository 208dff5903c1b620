/* fresnel.h — how much light a smooth interface reflects, and where it
 * refracts the rest; shared by the kernels and the host.
 *
 *  - fresnel_dielectric: the exact reflectance for unpolarised light of the
 *    interface between two dielectrics, the mean of the s and p reflectances
 *    (Pharr, Jakob and Humphreys, Physically Based Rendering, 4th ed., 9.3).
 *    eta = n_inside / n_outside, the inside being the side the normal points
 *    away from; cos_i < 0 means the light arrives from the inside, where eta
 *    becomes 1 / eta. Past the critical angle the result is exactly 1 (total
 *    internal reflection).
 *  - fresnel_schlick: Schlick's approximation F0 + (1 - F0)(1 - cos)^5, per
 *    channel, as glTF 2.0's metallic-roughness model uses it (Appendix B):
 *    F0 = 0.04 for the dielectric base (eta = 1.5; fresnel_f0 gives it for
 *    another ior, as KHR_materials_ior does), F0 = base colour for a metal.
 *    Schlick's formula is linear in F0, so mixing the two F0 by metallic mixes
 *    the two reflectances by metallic, as the spec's mix(dielectric, metal)
 *    asks. |cos| is used: the approximation has no inside. */
#ifndef WF_FRESNEL_H
#define WF_FRESNEL_H

#include "wavefront/compat.h"

WF_DEVICE_BEGIN

WF_INLINE float fresnel_dielectric(float cos_i, float eta) {
    cos_i = min(max(cos_i, -1.0f), 1.0f);
    if (cos_i < 0.0f) {
        eta = 1.0f / eta;
        cos_i = -cos_i;
    }
    const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f) return 1.0f;
    const float cos_t = sqrt(max(0.0f, 1.0f - sin2_t));
    /* cos_i = cos_t = 0 cannot happen: sin2_t < 1 keeps cos_t > 0. */
    const float r_parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float r_perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

/* The reflectance at normal incidence of an interface of relative index eta. */
WF_INLINE float fresnel_f0(float eta) {
    const float r = (eta - 1.0f) / (eta + 1.0f);
    return r * r;
}

/* wo refracted through the plane of normal n (either side), relative index
 * eta; 0 on total internal reflection. */
WF_INLINE int fresnel_refract(float3 wo, float3 n, float eta, float3* wt) {
    float cos_i = dot(n, wo);
    if (cos_i < 0.0f) {
        eta = 1.0f / eta;
        cos_i = -cos_i;
        n = -n;
    }
    const float sin2_t = max(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f) return 0;
    const float cos_t = sqrt(1.0f - sin2_t);
    *wt = -wo / eta + (cos_i / eta - cos_t) * n;
    return 1;
}

WF_INLINE float schlick_weight(float cos_i) {
    const float m = 1.0f - min(fabs(cos_i), 1.0f);
    const float m2 = m * m;
    return m2 * m2 * m;
}

WF_INLINE float3 fresnel_schlick(float3 f0, float cos_i) {
    return f0 + (make_float3(1.0f, 1.0f, 1.0f) - f0) * schlick_weight(cos_i);
}

WF_INLINE float fresnel_schlick_scalar(float f0, float cos_i) {
    return f0 + (1.0f - f0) * schlick_weight(cos_i);
}

WF_DEVICE_END

#endif /* WF_FRESNEL_H */
