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

double regularized_gamma_q(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double log_prefactor = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) { // P by its series, Q = 1 - P
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 1000 && std::fabs(term) > 1e-16 * std::fabs(sum); ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return std::max(0.0, 1.0 - sum * std::exp(log_prefactor));
    }
    const double tiny = 1e-300; // Q by its continued fraction (modified Lentz)
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int n = 1; n < 1000; ++n) {
        const double an = -n * (n - a);
        b += 2.0;
        d = an * d + b;
        d = std::fabs(d) < tiny ? tiny : d;
        c = b + an / c;
        c = std::fabs(c) < tiny ? tiny : c;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-16) break;
    }
    return std::exp(log_prefactor) * h;
}

double chi_square_p_value(const std::vector<double>& observed, const std::vector<double>& expected,
                          double min_expected) {
    double chi2 = 0.0, pooled_observed = 0.0, pooled_expected = 0.0;
    size_t cells = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] <= 0.0 && observed[i] > 0.0) return 0.0;
        if (expected[i] < min_expected) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
        } else {
            chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
            ++cells;
        }
    }
    if (pooled_expected >= min_expected) {
        chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
        ++cells;
    }
    if (cells < 2) return 1.0;
    return regularized_gamma_q(0.5 * double(cells - 1), 0.5 * chi2);
}

} // namespace wf::test
