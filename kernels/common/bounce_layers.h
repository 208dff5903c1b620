/* bounce_layers.h — the per-bounce film (--aov bounces): radiance that
 * reached the camera after 0, 1, 2, ... reflections, each in its own layer,
 * the last layer holding everything from its count on. Contributions are added
 * where they arise (emitter hits in shade, light samples in intersect_shadow);
 * a pixel's owning slot is its only writer, so no atomics are needed. */
#ifndef WF_BOUNCE_LAYERS_H
#define WF_BOUNCE_LAYERS_H

#include "wavefront/compat.h"
#include "wavefront/render_params.h"
#include "film_view.h"
#include "common/film_add.h"
#include "common/finite.h"

/* Adds radiance that arrived after `bounces` reflections, when the render keeps layers. */
WF_INLINE void add_to_bounce_layer(const RenderParams* params, const FilmBuffers* film, uint pixel, uint bounces,
                                float3 radiance) {
    if (params->bounce_layers == 0u || !is_finite3(radiance)) return;
    const uint layer = min(bounces, params->bounce_layers - 1u);
    film_add(film->layers, film->layer_compensation, layer * params->pixel_count + pixel, (float4)(radiance, 0.0f));
}

#endif
