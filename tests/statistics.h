// statistics.h — comparing two renders statistically: each image carries the
// variance of every pixel's mean, so a difference can be judged against noise.
#pragma once

#include <cstdint>
#include <vector>

#include "film.h"

namespace wf::test {

// The largest |z| over square blocks of `block` pixels and the three channels
// of (a − b), each block's variance the sum of both images' variances of the
// mean. Blocks average away pixels whose own variance is poorly estimated.
double max_block_z(const FilmReadout& a, const FilmReadout& b, uint32_t block);

// The two-sided |z| threshold at which `comparisons` independent tests have a
// family-wise false-alarm probability of at most `alpha` (Bonferroni).
double bonferroni_threshold(double alpha, size_t comparisons);

// Q(a, x) = Γ(a, x) / Γ(a), the regularized upper incomplete gamma function
// (series for x < a + 1, else Lentz's continued fraction; Numerical Recipes 6.2).
double regularized_gamma_q(double a, double x);

// Pearson's chi-square test that `observed` counts come from the distribution
// whose `expected` counts (same total) are given, as pbrt-v4 and Mitsuba test
// samplers: cells expected below `min_expected` are pooled into one (dropped
// if the pool stays below it), and the statistic is referred to chi-square
// with (cells - 1) degrees of freedom. Returns the p-value; 0 when a cell
// with no expectation at all received samples.
double chi_square_p_value(const std::vector<double>& observed, const std::vector<double>& expected,
                          double min_expected = 5.0);

} // namespace wf::test
