/* film_buffers.h — the film's buffers on the device, declared once: what the
 * kernels add radiance to (kernels/common/film_add.h) and the host reads back
 * (host/film/film.h). Each pixel has one writer, the path slot that owns it,
 * so none needs atomics.
 *
 * The list expands into the kernels' parameters and the Film they gather them
 * into (kernels/kernel_params.h), the host's buffers, and the loop that binds
 * them (host/integrator/stage_args.cpp).
 *   X(element type, name, what it holds) */
#ifndef WAVEFRONT_FILM_BUFFERS_H
#define WAVEFRONT_FILM_BUFFERS_H

#define WF_FILM_BUFFERS(X)                                                                            \
    X(float4, sum, "per pixel: the sum of its samples (xyz)")                                         \
    X(float4, compensation, "per pixel: what the sum's additions rounded away")                       \
    X(float4, sum_squares, "per pixel: the sum of its samples' squares")                              \
    X(float4, squares_compensation, "per pixel: likewise for the squares")                            \
    X(uint32_t, samples, "per pixel: samples added")                                                  \
    X(float4, layers, "per layer and pixel: radiance after that many bounces (--aov bounces)")        \
    X(float4, layer_compensation, "per layer and pixel: likewise compensated")

#endif /* WAVEFRONT_FILM_BUFFERS_H */
