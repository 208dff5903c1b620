/* path_state.h — what the stages pass to each other: the per-render constants,
 * the queues, the statistics counters, and the path state of every slot.
 *
 * The path state is a structure of arrays declared once, by WF_PATH_STATE: the
 * host allocates one buffer per field (host/integrator/path_pool.cpp) and sets
 * them in the same order (host/integrator/stage_args.cpp); every stage kernel takes them
 * in this order within WF_STAGE_PARAMS (kernels/kernel_params.h), and the stage
 * functions see them as one PathState (kernels/path_state.h), so host and
 * device cannot disagree on what a slot holds. */
#ifndef WAVEFRONT_PATH_STATE_H
#define WAVEFRONT_PATH_STATE_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"

/* Constants of one render, passed by value to every stage kernel. */
typedef struct RenderParams {
    uint32_t pixel_count;    /* of the image */
    uint32_t first_pixel;    /* the pool traces pixels [first_pixel, first_pixel + traced_pixels): */
    uint32_t traced_pixels;  /* the whole image, or one device's unit of work (host/render/) */
    uint32_t pool_size;      /* path slots; slot i owns pixels first + i, first + i + pool, ... */
    uint32_t spp;            /* samples per pixel to reach in the current round */
    uint32_t max_depth;      /* bounces; WF_UNLIMITED_DEPTH = ended by roulette alone */
    uint32_t seed;
    uint32_t roulette_depth; /* first depth at which roulette may end a path */
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


/* The first hit's layers a denoiser or compositor reads (--aov): its
 * material's base colour, its shading normal and its distance from the camera,
 * summed over a pixel's samples like radiance; 0 where the camera ray escapes. */
#define WF_AOV_ALBEDO 1u
#define WF_AOV_NORMAL 2u
#define WF_AOV_DEPTH 4u

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

/* The queues: index buffers of path slots, one region of pool_size entries per
 * queue in one buffer, each with a counter in the counter buffer. A slot is in
 * one queue at a time, and each queue has one consumer, which takes it whole
 * before the host zeroes its counter (host/integrator/wavefront_scheduler.cpp); so the
 * stages may run in any order, and one extension queue serves both generate
 * and roulette. The numbering lets the refill schedule clear the counters of
 * each phase with one fill: [EXTEND, REGENERATE] once shade has consumed them,
 * the rest at the end of every iteration, after it has read them. */
#define WF_QUEUE_EXTEND 0     /* paths whose ray needs a closest hit, then shading */
#define WF_QUEUE_REGENERATE 1 /* free slots, to receive the next camera sample */
#define WF_QUEUE_SHADOW 2     /* paths with a pending shadow ray, before roulette or accumulation */
#define WF_QUEUE_CONTINUE 3   /* shaded paths with a new ray, before roulette */
#define WF_QUEUE_FINISHED 4   /* ended paths, to accumulate */
#define WF_QUEUE_COUNT 5

/* Statistics the kernels count, after the queue lengths in the same buffer so
 * one read returns both. */
#define WF_COUNTER_CLOSEST_RAYS 5
#define WF_COUNTER_SHADOW_RAYS 6
#define WF_COUNTER_NONFINITE 7 /* samples dropped for a NaN or Inf component */
/* Finished paths by bounce count, in power-of-two buckets: 0, 1, 2–3, 4–7, ...,
 * the last open-ended. */
#define WF_COUNTER_PATH_LENGTHS 8
#define WF_PATH_LENGTH_BUCKETS 16
#define WF_COUNTER_COUNT (WF_COUNTER_PATH_LENGTHS + WF_PATH_LENGTH_BUCKETS)

/* --sort-materials: the keys of the counting sort of the extension queue by
 * material (kernels/stages/sort_by_material.h); materials beyond share keys. */
#define WF_SORT_KEYS 256

/* In shadow_radiance.w: the path has a new ray to follow once its shadow ray is traced. */
#define WF_SHADOW_THEN_CONTINUE 0x80000000u

/* The path state: a structure of arrays, one array per field, each indexed by
 * path slot. Declared once here; the host allocates a buffer per field and the
 * kernels receive them as one parameter list, in this order. Eight float4s,
 * 128 bytes a path: counts ride in w lanes (read through kernels/path_state.h),
 * and the pixel and sample index follow from the count of samples started.
 *   X(type, name, what-it-holds) */
#define WF_PATH_STATE(X)                                                             \
    X(float4, ray_origin, "xyz: origin of the ray to trace")                         \
    X(float4, ray_direction, "xyz: direction (unit); w: solid-angle pdf it was sampled with") \
    X(float4, hit, "closest hit: t, barycentric u, v; w: triangle as bits (-1 = miss)") \
    X(float4, throughput, "rgb: path throughput; w: bounces so far, 0 for a camera ray, as bits") \
    X(float4, radiance, "rgb: radiance gathered so far; w: samples the slot has started, as bits") \
    X(float4, shadow_origin, "xyz: shadow ray origin")                               \
    X(float4, shadow_segment, "xyz: vector to the light point; visible when no hit in (0, 1)") \
    X(float4, shadow_radiance, "rgb: added to radiance when the shadow ray is unoccluded; w: bounce layer | WF_SHADOW_THEN_CONTINUE, as bits")

#endif /* WAVEFRONT_PATH_STATE_H */
