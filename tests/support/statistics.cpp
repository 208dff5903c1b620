// statistics.cpp — see statistics.h.
#include "support/statistics.h"

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
    const double log_prefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) {
        // P(a, x) = e^-x x^a / Γ(a + 1) Σ x^n / ((a + 1)...(a + n)).
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 100000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::fabs(term) < std::fabs(sum) * 1e-16) break;
        }
        return std::max(0.0, 1.0 - sum * std::exp(log_prefix));
    }
    // Q(a, x) = e^-x x^a / Γ(a) · 1/(x + 1 - a - 1(1 - a)/(x + 3 - a - ...)).
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-16) break;
    }
    return std::exp(log_prefix) * h;
}

ChiSquare chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected,
                          double min_expected, double stray_fraction) {
    ChiSquare result;
    double total = 0.0;
    for (double o : observed) total += o;
    double pooled_observed = 0.0, pooled_expected = 0.0;
    int cells = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 1e-9 && observed[i] > stray_fraction * total) {
            result.p_value = 0.0;
            return result;
        }
        if (expected[i] < min_expected) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        const double diff = observed[i] - expected[i];
        result.statistic += diff * diff / expected[i];
        ++cells;
    }
    if (pooled_expected > 0.0 || pooled_observed > 0.0) {
        const double diff = pooled_observed - pooled_expected;
        result.statistic += diff * diff / std::max(pooled_expected, 1e-9);
        ++cells;
    }
    result.dof = cells - 1;
    result.p_value = result.dof > 0 ? regularized_gamma_q(0.5 * result.dof, 0.5 * result.statistic) : 1.0;
    return result;
}

} // namespace wf::test
