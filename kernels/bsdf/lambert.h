/* lambert.h — the Lambertian BRDF, f = albedo / pi, sampled by the cosine. All
 * directions are in the shading frame's world coordinates; n is the shading
 * normal on the side the light arrives from. */
#ifndef WF_LAMBERT_H
#define WF_LAMBERT_H

#include "common/sampling.h"

inline float3 lambert_eval(float3 albedo) { return albedo * WF_INV_PI; }

inline float lambert_pdf(float3 n, float3 wi) { return max(dot(n, wi), 0.0f) * WF_INV_PI; }

/* A direction about n with density cos / pi; f · cos / pdf is then the albedo. */
inline float3 lambert_sample(float3 n, float2 u) {
    float3 t, b;
    orthonormal_basis(n, &t, &b);
    const float3 d = sample_cosine_hemisphere(u);
    return d.x * t + d.y * b + d.z * n;
}

#endif
