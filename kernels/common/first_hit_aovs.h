/* first_hit_aovs.h — the layers a denoiser or compositor reads (--aov
 * albedo,normal,depth): at a camera ray's end, the base colour of the
 * material it hit, its shading normal (world space, facing the camera) and
 * its distance, added to the pixel's sums like radiance, so a pixel holds
 * their mean over its samples; an escaped ray adds nothing (zeros). A render
 * option, not a scene feature: compiled only where a render keeps them
 * (-DWF_HAS_AOVS=1); a pixel's owning slot is its only writer, so no atomics
 * are needed. */
#ifndef WF_FIRST_HIT_AOVS_H
#define WF_FIRST_HIT_AOVS_H

#include "wavefront/compat.h"
#include "wavefront/render_params.h"
#include "film_view.h"

#ifndef WF_HAS_AOVS
#define WF_HAS_AOVS 0
#endif

WF_INLINE void add_first_hit_aovs(const FilmBuffers* film, uint pixel, float3 albedo, float3 normal, float distance) {
    film->aov_albedo[pixel] += (float4)(albedo, 0.0f);
    film->aov_normal_depth[pixel] += (float4)(normal, distance);
}

#endif
