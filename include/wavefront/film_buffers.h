/* film_buffers.h — the film's buffers on the device, declared once: what the
 * kernels add radiance to (kernels/common/film_add.h) and the host reads back
 * (host/film/film.h). Each pixel has one writer, the path slot that owns it,
 * so none needs atomics.
 *
 * The list expands into the kernels' parameters and the Film they gather them
 * into (kernels/kernel_params.h), the host's buffers, the loop that binds
 * them (host/integrator/stage_args.cpp) and the host's copy of them
 * (FilmState, host/film/film.h).
 *   X(element type, name, PIXEL: one element per pixel, LAYER: one per bounce
 *     layer and pixel, layer by layer, or AOV: one per pixel when the render
 *     keeps any of albedo, normal, depth; what an element holds) */
#ifndef WAVEFRONT_FILM_BUFFERS_H
#define WAVEFRONT_FILM_BUFFERS_H

#define WF_FILM_BUFFERS(X)                                                                            \
    X(float4, sum, PIXEL, "the sum of its samples (xyz)")                                             \
    X(float4, compensation, PIXEL, "what the sum's additions rounded away")                           \
    X(float4, sum_squares, PIXEL, "the sum of its samples' squares")                                  \
    X(float4, squares_compensation, PIXEL, "likewise for the squares")                                \
    X(uint32_t, samples, PIXEL, "samples added")                                                      \
    X(float4, layers, LAYER, "radiance after that many bounces (--aov bounces)")                      \
    X(float4, layer_compensation, LAYER, "likewise compensated")                                      \
    X(float4, aov_albedo, AOV, "the first hit's base colour, summed (--aov albedo)")                  \
    X(float4, aov_normal_depth, AOV, "its shading normal (xyz) and distance (w), summed")

#endif /* WAVEFRONT_FILM_BUFFERS_H */
