// statistics.h — comparing two renders statistically: each image carries the
// variance of every pixel's mean, so a difference can be judged against noise.
#pragma once

#include <cstdint>
#include <vector>

#include "film/film.h"

namespace wf::test {

// The largest |z| over square blocks of `block` pixels and the three channels
// of (a − b), each block's variance the sum of both images' variances of the
// mean. Blocks average away pixels whose own variance is poorly estimated.
double max_block_z(const FilmReadout& a, const FilmReadout& b, uint32_t block);

// The two-sided |z| threshold at which `comparisons` independent tests have a
// family-wise false-alarm probability of at most `alpha` (Bonferroni).
double bonferroni_threshold(double alpha, size_t comparisons);

// Q(a, x) = Γ(a, x) / Γ(a), the regularized upper incomplete gamma function
// (series below a + 1, Lentz's continued fraction above; Numerical Recipes
// 6.2), accurate to ~1e-14 for a > 0, x >= 0.
double regularized_gamma_q(double a, double x);

// Pearson's chi-square test of observed counts against expected counts, with
// the cells whose expectation is below `min_expected` pooled into one (as in
// pbrt-v4's and Mitsuba's BSDF tests). The p-value is Q(dof / 2, chi² / 2).
// A cell expected to be empty (below 1e-9) that holds more than
// `stray_fraction` of all observations makes the p-value 0: the sampler puts
// samples where its density says none can be.
struct ChiSquare {
    double statistic = 0.0;
    int dof = 0;
    double p_value = 1.0;
};
ChiSquare chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected,
                          double min_expected = 5.0, double stray_fraction = 1e-5);

} // namespace wf::test
