/* techniques.h — the sampling techniques a render chooses among, as
 * RenderParams holds them (--light-sampling, --hemisphere, --sampler,
 * --max-depth). */
#ifndef WAVEFRONT_TECHNIQUES_H
#define WAVEFRONT_TECHNIQUES_H

/* How emitters are found: by BRDF sampling alone, by next-event estimation
 * alone, or both weighted by the power heuristic. */
#define WF_LIGHT_SAMPLING_BSDF 0u
#define WF_LIGHT_SAMPLING_NEE 1u
#define WF_LIGHT_SAMPLING_MIS 2u

/* How the Lambertian lobe chooses directions: pdf 1/2pi, or cos/pi. */
#define WF_HEMISPHERE_UNIFORM 0u
#define WF_HEMISPHERE_COSINE 1u

/* Where sample values come from: hashed independent numbers, or an
 * Owen-scrambled Sobol sequence. Both are functions of (pixel, sample, bounce). */
#define WF_SAMPLER_INDEPENDENT 0u
#define WF_SAMPLER_SOBOL 1u

#define WF_UNLIMITED_DEPTH 0xffffffffu

#endif /* WAVEFRONT_TECHNIQUES_H */
