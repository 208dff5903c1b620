// statistics.h — comparing two renders statistically: each image carries the
// variance of every pixel's mean, so a difference can be judged against noise.
#pragma once

#include <cstdint>

#include "film.h"

namespace wf::test {

// The largest |z| over square blocks of `block` pixels and the three channels
// of (a − b), each block's variance the sum of both images' variances of the
// mean. Blocks average away pixels whose own variance is poorly estimated.
double max_block_z(const FilmReadout& a, const FilmReadout& b, uint32_t block);

// The two-sided |z| threshold at which `comparisons` independent tests have a
// family-wise false-alarm probability of at most `alpha` (Bonferroni).
double bonferroni_threshold(double alpha, size_t comparisons);

} // namespace wf::test
