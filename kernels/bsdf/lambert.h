/* lambert.h — the Lambertian BRDF, f = albedo / pi, sampled either uniformly
 * over the hemisphere (pdf 1 / 2pi) or by the cosine (pdf cos / pi, which makes
 * f · cos / pdf the albedo itself). n is the shading normal on the side the
 * light arrives from. */
#ifndef WF_LAMBERT_H
#define WF_LAMBERT_H

#include "wavefront/path_state.h"
#include "common/sampling.h"

inline float3 lambert_eval(float3 albedo) { return albedo * WF_INV_PI; }

inline float lambert_pdf(float3 n, float3 wi, uint hemisphere) {
    const float cos_theta = dot(n, wi);
    if (cos_theta <= 0.0f) return 0.0f;
    return hemisphere == WF_HEMISPHERE_COSINE ? cos_theta * WF_INV_PI : 0.5f * WF_INV_PI;
}

inline float3 lambert_sample(float3 n, float2 u, uint hemisphere) {
    float3 t, b;
    orthonormal_basis(n, &t, &b);
    const float3 d = hemisphere == WF_HEMISPHERE_COSINE ? sample_cosine_hemisphere(u) : sample_uniform_hemisphere(u);
    return d.x * t + d.y * b + d.z * n;
}

#endif
