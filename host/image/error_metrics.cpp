// error_metrics.cpp — sums in double over every pixel and channel.
#include "image/error_metrics.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/errors.h"
#include "image/image_io.h"

namespace wf {
namespace {
constexpr double kRelativeEpsilon = 0.01;
}

float as_stored(float linear, const Quantisation& q) {
    if (q.levels == 0) return linear;
    const float levels = float(q.levels);
    const float x = std::clamp(std::isnan(linear) ? 0.0f : linear * std::exp2(q.exposure), 0.0f, 1.0f);
    if (!q.srgb) return std::round(x * levels) / levels;
    return srgb_decode(std::round(srgb_encode(x) * levels) / levels);
}

ErrorMetrics compare_images(const Image& image, const Image& reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw InputError("the reference is " + std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                         " but the render is " + std::to_string(image.width) + "x" + std::to_string(image.height));
    ErrorMetrics e;
    const size_t n = image.rgb.size();
    for (size_t i = 0; i < n; ++i) {
        const double x = as_stored(image.rgb[i], reference.stored), y = reference.rgb[i], d = x - y;
        e.mse += d * d;
        e.relmse += d * d / (y * y + kRelativeEpsilon);
        e.mae += std::fabs(d);
    }
    e.mse /= n;
    e.relmse /= n;
    e.mae /= n;
    return e;
}

double estimate_pixel_relmse(const Image& mean, const Image& variance_of_mean, size_t pixel) {
    double sum = 0.0;
    for (size_t i = 3 * pixel; i < 3 * pixel + 3; ++i) {
        const double x = mean.rgb[i];
        sum += variance_of_mean.rgb[i] / (x * x + kRelativeEpsilon);
    }
    return sum / 3.0;
}

double estimate_relmse(const Image& mean, const Image& variance_of_mean) {
    const size_t pixels = mean.rgb.size() / 3;
    double sum = 0.0;
    for (size_t p = 0; p < pixels; ++p) sum += estimate_pixel_relmse(mean, variance_of_mean, p);
    return sum / pixels;
}

} // namespace wf
