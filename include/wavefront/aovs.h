/* aovs.h — the bits of RenderParams.aovs (--aov), and of the film's layers. */
#ifndef WAVEFRONT_AOVS_H
#define WAVEFRONT_AOVS_H

/* The first hit's layers a denoiser or compositor reads (--aov): its
 * material's base colour, its shading normal and its distance from the camera,
 * summed over a pixel's samples like radiance; 0 where the camera ray escapes. */
#define WF_AOV_ALBEDO 1u
#define WF_AOV_NORMAL 2u
#define WF_AOV_DEPTH 4u
#define WF_AOV_FIRST_HIT (WF_AOV_ALBEDO | WF_AOV_NORMAL | WF_AOV_DEPTH)
/* How many samples each pixel took (adaptive sampling's): the film counts
 * them anyway, so this layer asks nothing of the kernels. */
#define WF_AOV_SAMPLES 8u

#endif /* WAVEFRONT_AOVS_H */
