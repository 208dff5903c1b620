// adaptive_sampling.cpp — two 3×3 passes over the image: the mean of the
// pixels' estimated errors, then whether any of a pixel's neighbours is at or
// above the target. Windows are cut at the image's border.
#include "render/adaptive_sampling.h"

#include <algorithm>
#include <numeric>

#include "image/error_metrics.h"

namespace wf {
namespace {

// Calls f(neighbour) for each pixel of the 3×3 window about (x, y) inside the
// image.
template <class F> void for_each_in_window(uint32_t width, uint32_t height, uint32_t x, uint32_t y, F f) {
    for (uint32_t ny = y > 0 ? y - 1 : 0; ny <= std::min(y + 1, height - 1); ++ny)
        for (uint32_t nx = x > 0 ? x - 1 : 0; nx <= std::min(x + 1, width - 1); ++nx) f(size_t{ny} * width + nx);
}

} // namespace

std::vector<uint32_t> unfinished_pixels(const Image& mean, const Image& variance_of_mean, double target,
                                        const std::vector<uint32_t>& going_on) {
    const uint32_t width = mean.width, height = mean.height;
    const size_t pixels = size_t{width} * height;
    std::vector<double> error(pixels);
    for (size_t p = 0; p < pixels; ++p) error[p] = estimate_pixel_relmse(mean, variance_of_mean, p);
    std::vector<char> above(pixels);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            double sum = 0.0;
            int count = 0;
            for_each_in_window(width, height, x, y, [&](size_t n) { sum += error[n], ++count; });
            above[size_t{y} * width + x] = sum / count >= target;
        }
    std::vector<uint32_t> unfinished;
    for (const uint32_t p : going_on) {
        bool near = false;
        for_each_in_window(width, height, p % width, p / width, [&](size_t n) { near = near || above[n]; });
        if (near) unfinished.push_back(p);
    }
    return unfinished;
}

std::vector<uint32_t> every_pixel(uint32_t width, uint32_t height) {
    std::vector<uint32_t> all(size_t{width} * height);
    std::iota(all.begin(), all.end(), 0u);
    return all;
}

} // namespace wf
