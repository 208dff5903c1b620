/* path_state.h — what the stages pass to each other: the path state of every
 * slot. (The render's constants are render_params.h's, the queues
 * stage_graph.h's, the statistics counters.h's.)
 *
 * The path state is a structure of arrays declared once, by WF_PATH_STATE: the
 * host allocates one buffer per field (host/integrator/path_pool.cpp) and sets
 * them in the same order (host/integrator/stage_args.cpp); every stage kernel takes them
 * in this order within WF_STAGE_PARAMS (kernels/kernel_params.h), and the stage
 * functions see them as one PathState (kernels/path_view.h), so host and
 * device cannot disagree on what a slot holds. */
#ifndef WAVEFRONT_PATH_STATE_H
#define WAVEFRONT_PATH_STATE_H

#include "wavefront/compat.h"

/* In shadow_radiance.w: the path has a new ray to follow once its shadow ray is traced. */
#define WF_SHADOW_THEN_CONTINUE 0x80000000u

/* The path state: a structure of arrays, one array per field, each indexed by
 * path slot. Declared once here; the host allocates a buffer per field and the
 * kernels receive them as one parameter list, in this order. Eight float4s,
 * 128 bytes a path: counts ride in w lanes (read through kernels/path_view.h),
 * and the pixel and sample index follow from the count of samples started.
 *   X(type, name, what-it-holds) */
#define WF_PATH_STATE(X)                                                             \
    X(float4, ray_origin, "xyz: origin of the ray to trace; w: the number roulette draws for it") \
    X(float4, ray_direction, "xyz: direction (unit); w: solid-angle pdf it was sampled with") \
    X(float4, hit, "closest hit: t, barycentric u, v; w: triangle as bits (-1 = miss)") \
    X(float4, throughput, "rgb: path throughput; w: bounces so far, 0 for a camera ray, as bits") \
    X(float4, radiance, "rgb: radiance gathered so far; w: samples the slot has started, as bits") \
    X(float4, shadow_origin, "xyz: shadow ray origin")                               \
    X(float4, shadow_segment, "xyz: vector to the light point; visible when no hit in (0, 1); w: the closest hit's placement as bits, where the scene has instances") \
    X(float4, shadow_radiance, "rgb: added to radiance when the shadow ray is unoccluded; w: bounce layer | WF_SHADOW_THEN_CONTINUE, as bits")

#endif /* WAVEFRONT_PATH_STATE_H */
