/* render_params.h — the constants of one render, passed by value to every
 * stage kernel (kernels/kernel_params.h); what its technique fields hold is
 * techniques.h's, its AOV bits aovs.h's. */
#ifndef WAVEFRONT_RENDER_PARAMS_H
#define WAVEFRONT_RENDER_PARAMS_H

#include "wavefront/compat.h"
#include "wavefront/aovs.h"
#include "wavefront/scene_types.h"
#include "wavefront/techniques.h"

typedef struct RenderParams {
    uint32_t pixel_count;    /* of the image */
    uint32_t first_pixel;    /* the pool traces pixels [first_pixel, first_pixel + traced_pixels): */
    uint32_t traced_pixels;  /* the whole image, or one device's unit of work (host/render/); */
    uint32_t pixel_list;     /* or, when 1, the pixels the list holds from entry first_pixel on (adaptive sampling's) */
    uint32_t pool_size;      /* path slots; slot i owns pixels first + i, first + i + pool, ... */
    uint32_t spp;            /* samples per pixel to reach in the current round */
    uint32_t max_depth;      /* bounces; WF_UNLIMITED_DEPTH = ended by roulette alone */
    uint32_t seed;
    uint32_t roulette_depth; /* first depth at which roulette may end a path */
    float roulette_cap;      /* the most a path's survival probability may be: 1 keeps q = max throughput */
    uint32_t light_count;    /* entries in the light table */
    uint32_t light_sampling; /* WF_LIGHT_SAMPLING_* */
    uint32_t hemisphere;     /* WF_HEMISPHERE_* */
    uint32_t sampler;        /* WF_SAMPLER_* */
    uint32_t bounce_layers;  /* film layers by bounce count (0: none), the last one open-ended */
    uint32_t environment_light; /* its entry in the light table; WF_NO_LIGHT without one */
    float scene_diameter;    /* of the scene's bounds: a shadow ray toward infinity stops past them */
    uint32_t aovs;           /* WF_AOV_* bits: what the first hit adds to the film beside radiance */
    Environment environment; /* valid when environment_light != WF_NO_LIGHT */
} RenderParams;

#endif /* WAVEFRONT_RENDER_PARAMS_H */
