/* sheen.h — KHR_materials_sheen's lobe, the back-scattering of fibres (cloth,
 * velvet), in the local shading frame; shared by the kernels and the host.
 *
 * The "Charlie" distribution of Estevez and Kulla ("Production Friendly
 * Microfacet Sheen BRDF", 2017), D(wh) = (2 + 1/a) sin(theta_h)^(1/a) / (2 pi),
 * a = roughness^2, with the visibility of Neubelt and Pettineo ("Crafting a
 * Next-Gen Material Pipeline for The Order: 1886", 2013),
 * V = 1 / (4 (mu_i + mu_o - mu_i mu_o)): glTF's own choice. f = colour D V.
 * Below WF_SHEEN_MIN_ROUGHNESS the exponent 1/a overflows float's precision
 * for sin(theta_h) near 1, so the roughness is clamped there, as Filament does.
 * Its directional albedo E_s(mu, r) (the table in albedo_tables.h, from this
 * code) tells the BSDF how much light the sheen takes from the layers below.
 *
 * Sampling (sheen_sample_mu, sheen_sample_pdf): below roughness 0.5 the lobe
 * lies along the horizon, where the cosine draws almost nothing (weights up
 * to 41 at grazing views). A cosine from an exponential truncated to [0, 1],
 * of rate 0.5 / roughness, with a uniform azimuth, follows it well enough that
 * no weight of the lobe alone passes 4 at any view and roughness (a numeric
 * search over both); at roughness 1 it is almost uniform. */
#ifndef WF_SHEEN_H
#define WF_SHEEN_H

#include "wavefront/compat.h"
#include "common/sampling.h"

#define WF_SHEEN_MIN_ROUGHNESS 0.07f

WF_DEVICE_BEGIN

WF_INLINE float sheen_alpha(float roughness) {
    const float r = max(roughness, WF_SHEEN_MIN_ROUGHNESS);
    return r * r;
}

/* D V for wo.z > 0 and wi.z > 0, without the colour. */
WF_INLINE float sheen_eval(float3 wo, float3 wi, float roughness) {
    const float3 sum = wo + wi;
    const float len2 = dot(sum, sum);
    if (!(len2 > 0.0f) || !(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    const float cos2_h = sum.z * sum.z / len2;
    const float sin2_h = max(1.0f - cos2_h, 0.0f);
    const float inv_alpha = 1.0f / sheen_alpha(roughness);
    /* sin2_h^(1 / 2 alpha) as exp2 of a product: PoCL's general pow, with its
     * cases for negative bases and integral exponents, was 5% of ToyCar. */
    const float d = (2.0f + inv_alpha) * exp2(0.5f * inv_alpha * log2(sin2_h)) * (0.5f * WF_INV_PI);
    const float v = 1.0f / (4.0f * (wi.z + wo.z - wi.z * wo.z));
    return d * v;
}

/* The rate of the sampled cosine's exponential. */
WF_INLINE float sheen_sample_rate(float roughness) { return 0.5f / sqrt(sheen_alpha(roughness)); }

/* A cosine in [0, 1) from u in [0, 1); the azimuth is uniform. */
WF_INLINE float sheen_sample_mu(float roughness, float u) {
    const float rate = sheen_sample_rate(roughness);
    return -log(1.0f - u * (1.0f - exp(-rate))) / rate;
}

/* The solid-angle density of that procedure at cosine mu. */
WF_INLINE float sheen_sample_pdf(float roughness, float mu) {
    if (!(mu > 0.0f)) return 0.0f;
    const float rate = sheen_sample_rate(roughness);
    return rate * exp(-rate * mu) / ((1.0f - exp(-rate)) * 2.0f * WF_PI);
}

WF_DEVICE_END

#endif /* WF_SHEEN_H */
