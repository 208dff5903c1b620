// adaptive_sampling.h — which pixels go on taking samples (--adaptive): after
// a minimum, a pixel stops once the relative error its own variance estimates
// (error_metrics.h), averaged over its 3×3 neighbourhood, is below the target,
// unless a neighbour still goes on. The average keeps a pixel whose few
// samples happen to agree (all of them missing a small light) from stopping
// on its own; the neighbours keep an edge between noisy and quiet regions
// sampled on both sides. Cycles' adaptive sampling does the same two things.
//
// A pixel that stopped never starts again, so every pixel still going on has
// the samples of the round it last took part in: the next round continues
// them all from one count (Renderer::render_pixels_to). Each pixel's samples
// are those a uniform render takes, so a pixel that stopped at N samples has
// the bytes of a uniform render of N, and the same flags and seed stop the
// same pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"

namespace wf {

// Of `going_on` (pixel indices, row-major, ascending), those whose error says
// they go on: the 3×3 mean of estimate_pixel_relmse is at least `target` at
// the pixel or at one of its eight neighbours.
std::vector<uint32_t> unfinished_pixels(const Image& mean, const Image& variance_of_mean, double target,
                                        const std::vector<uint32_t>& going_on);

// Every pixel of an image of this size: where adaptive sampling starts.
std::vector<uint32_t> every_pixel(uint32_t width, uint32_t height);

} // namespace wf
