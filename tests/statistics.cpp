// statistics.cpp — see statistics.h.
#include "statistics.h"

#include <algorithm>
#include <cmath>

namespace wf::test {

double max_block_z(const FilmReadout& a, const FilmReadout& b, uint32_t block) {
    const uint32_t w = a.mean.width, h = a.mean.height;
    double worst = 0.0;
    for (uint32_t by = 0; by + block <= h; by += block)
        for (uint32_t bx = 0; bx + block <= w; bx += block)
            for (int c = 0; c < 3; ++c) {
                double difference = 0.0, variance = 0.0;
                for (uint32_t y = by; y < by + block; ++y)
                    for (uint32_t x = bx; x < bx + block; ++x) {
                        const size_t i = 3 * (size_t{y} * w + x) + c;
                        difference += double(a.mean.rgb[i]) - b.mean.rgb[i];
                        variance += double(a.variance_of_mean.rgb[i]) + b.variance_of_mean.rgb[i];
                    }
                if (variance > 0.0) worst = std::max(worst, std::fabs(difference) / std::sqrt(variance));
            }
    return worst;
}

double bonferroni_threshold(double alpha, size_t comparisons) {
    // Bisection on the two-sided Gaussian tail erfc(z / sqrt 2) = alpha / comparisons.
    const double target = alpha / comparisons;
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > target ? lo : hi) = mid;
    }
    return hi;
}

} // namespace wf::test
