/* accumulate — adds each finished path's radiance to its pixel and frees its slot.
 *
 * A pixel's samples all come from the one slot that owns it (stages/generate.h), so
 * each pixel has one writer and receives its samples in sample order: no
 * atomics, and the same sums whatever the pool size. Beside the sum, the sum of
 * squares gives each pixel's sample variance, from which the host estimates
 * the error of the image without a reference. Both sums are compensated. A
 * sample with a NaN or Inf component is counted and dropped, and every path is
 * counted by its bounce count (the path-length histogram of the report). */
#ifndef WF_STAGE_ACCUMULATE_H
#define WF_STAGE_ACCUMULATE_H

#include "wavefront/compat.h"
#include "path_view.h"
#include "film_view.h"
#include "common/finite.h"
#include "common/film_add.h"
#include "stages/stage_step.h"

/* Adds the slot's finished sample to its pixel; returns whether it was
 * dropped as non-finite. */
WF_INLINE bool accumulate_path(const PathState* path, const RenderParams* params, uint slot, const FilmBuffers* film) {
    const uint pixel = current_sample(path, params, slot).pixel;
    const float3 radiance = path->radiance[slot].xyz;
    const bool nonfinite = !is_finite3(radiance);
    const float4 x = nonfinite ? (float4)(0.0f) : (float4)(radiance, 0.0f);
    film_add(film->sum, film->compensation, pixel, x);
    film_add(film->sum_squares, film->squares_compensation, pixel, x * x);
    film->samples[pixel] += 1u;
    return nonfinite;
}

/* The sample into its pixel; the slot is free for its next. */
WF_FORCE_INLINE uint accumulate_step(const StageView* v, uint slot, StageTally* t) {
    t->nonfinite += accumulate_path(v->path, v->params, slot, v->film) ? 1u : 0u;
    return WF_QUEUE_REGENERATE;
}

/* The path-length histogram's bucket for a path of `bounces` bounces. */
WF_INLINE uint path_length_bucket(uint bounces) {
    return bounces == 0u ? 0u : min(32u - clz(bounces), (uint)WF_PATH_LENGTH_BUCKETS - 1u);
}

#endif
