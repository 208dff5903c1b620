// adaptive_sampling.cpp — each pixel's per-sample variance (its estimated
// relMSE times its samples), averaged over the 3×3 window cut at the image's
// border; λ from their square roots; then the pixels still short of √(v/λ).
#include "render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "image/error_metrics.h"

namespace wf {

AdaptiveSampling::AdaptiveSampling(uint32_t width, uint32_t height, double target)
    : width_(width), height_(height), target_(target), going_on_(size_t{width} * height),
      samples_(size_t{width} * height, 0u) {
    std::iota(going_on_.begin(), going_on_.end(), 0u);
}

void AdaptiveSampling::update(const FilmReadout& film, uint32_t samples) {
    for (const uint32_t p : going_on_) samples_[p] = samples;
    const size_t pixels = samples_.size();
    std::vector<double> variance(pixels);
    for (size_t p = 0; p < pixels; ++p)
        variance[p] = estimate_pixel_relmse(film.mean, film.variance_of_mean, p) * samples_[p];
    std::vector<double> smoothed(pixels);
    double sum_of_roots = 0.0;
    for (uint32_t y = 0; y < height_; ++y)
        for (uint32_t x = 0; x < width_; ++x) {
            double sum = 0.0;
            int count = 0;
            for (uint32_t ny = y > 0 ? y - 1 : 0; ny <= std::min(y + 1, height_ - 1); ++ny)
                for (uint32_t nx = x > 0 ? x - 1 : 0; nx <= std::min(x + 1, width_ - 1); ++nx, ++count)
                    sum += variance[size_t{ny} * width_ + nx];
            smoothed[size_t{y} * width_ + x] = sum / count;
            sum_of_roots += std::sqrt(sum / count);
        }
    const double mean_root = sum_of_roots / double(pixels);
    if (mean_root == 0.0) { // no variance anywhere: nothing more to learn
        going_on_.clear();
        return;
    }
    const double lambda = (target_ / mean_root) * (target_ / mean_root);
    std::vector<uint32_t> next;
    for (const uint32_t p : going_on_)
        if (smoothed[p] >= lambda * double(samples) * samples) next.push_back(p);
    going_on_ = std::move(next);
}

} // namespace wf
