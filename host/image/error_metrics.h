// error_metrics.h — how wrong an image is: against a reference when there is
// one, and estimated from the render's own per-pixel variance when there is not.
//
// relMSE is the mean over pixels and channels of (x − y)² / (y² + 0.01): the
// squared error relative to the value, with 0.01 keeping black pixels from
// dominating. The estimate replaces (x − y)² by the variance of the pixel's
// mean and y by x, its only available value.
#pragma once

#include <cstddef>

#include "image/image.h"

namespace wf {

struct ErrorMetrics {
    double mse = 0.0;
    double relmse = 0.0;
    double mae = 0.0;
};

// Throws InputError when the sizes differ. Against a quantised reference (an
// 8-bit PNG, say), `image` is first stored as the reference was: an identical
// render then has no error, instead of the error of the clipping.
ErrorMetrics compare_images(const Image& image, const Image& reference);

// `linear` as it reads back from a file quantised as `q`.
float as_stored(float linear, const Quantisation& q);

double estimate_relmse(const Image& mean, const Image& variance_of_mean);
// The same estimate for one pixel, over its three channels: the image's is
// the mean of its pixels'.
double estimate_pixel_relmse(const Image& mean, const Image& variance_of_mean, size_t pixel);

} // namespace wf
