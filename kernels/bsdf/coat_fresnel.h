/* coat_fresnel.h — the clear coat's reflectance (KHR_materials_clearcoat: a
 * dielectric of ior 1.5, Schlick with F0 0.04 and F90 1), and what it leaves
 * of the emission beneath it; shared by the kernels and the host.
 *
 * The coat's lobe (bsdf/bsdf.h) reflects with coat_fresnel. The coat covers
 * the emission too: glTF asks emission (1 - clearcoat F_c(mu_o)), mu_o the
 * view's cosine from the coat's normal (the shading normal here:
 * clearcoatNormalTexture is not read), so an emitter under a full coat shows
 * 0.96 of its emission head-on. Emission seen along a ray and emission that
 * light sampling draws are weighed alike (materials/surface_material.h), or
 * MIS would count the two differently; the light table weighs an emitter's
 * power by the cosine-weighted mean of that weight. */
#ifndef WF_COAT_FRESNEL_H
#define WF_COAT_FRESNEL_H

#include "wavefront/compat.h"
#include "bsdf/fresnel.h"

#define WF_BSDF_COAT_F0 0.04f /* KHR_materials_clearcoat: a dielectric of ior 1.5 */

WF_DEVICE_BEGIN

WF_INLINE float coat_fresnel(float cos_i) { return fresnel_schlick_scalar(WF_BSDF_COAT_F0, cos_i); }

/* What leaves a coat of weight `clearcoat` of the emission beneath it, toward
 * a view of cosine mu_o from the coat's normal. */
WF_INLINE float coat_emission_weight(float clearcoat, float mu_o) { return 1.0f - clearcoat * coat_fresnel(mu_o); }

/* Its mean over the hemisphere, weighted by the cosine, as power is:
 * 2 ∫ (1 - mu)^5 mu dmu = 1/21. */
WF_INLINE float coat_emission_mean(float clearcoat) {
    return 1.0f - clearcoat * (WF_BSDF_COAT_F0 + (1.0f - WF_BSDF_COAT_F0) / 21.0f);
}

WF_DEVICE_END

#endif /* WF_COAT_FRESNEL_H */
