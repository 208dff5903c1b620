// test_scatter.cpp — the scatter's own arithmetic (kernels/stages/scatter.inc)
// where it is not a restatement of a tested function: the one-float step that
// moves a spawned ray's origin off its surface, written by its bits, is
// OpenCL's nextafter toward the step's infinity, at widths 1 and 8, over the
// values where the bits do something special (zeros of either sign, the
// smallest subnormals, the largest finite floats, infinities, NaN) and random
// ones of every magnitude. The scatter as a whole is tested by its images
// (tests/integrator/test_determinism.cpp: every width gives width 1's bytes)
// and the offset's promise by tests/kernels/test_ray_offset.cpp.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "device/kernel_sources.h"
#include "support/test_support.h"

namespace wf {
namespace {

uint32_t bits(float x) {
    uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

bool same(float a, float b) { return std::isnan(a) ? std::isnan(b) : bits(a) == bits(b); }

TEST(Scatter, RoundAwayIsNextafterTowardTheStepsInfinity) {
    using limits = std::numeric_limits<float>;
    const float special[] = {0.0f, -0.0f, limits::denorm_min(), -limits::denorm_min(), limits::min(), -limits::min(),
                             limits::max(), -limits::max(), limits::infinity(), -limits::infinity(),
                             limits::quiet_NaN(), 1.0f, -1.0f};
    const float steps[] = {1e-3f, -1e-3f, 0.0f, -0.0f, limits::infinity()};
    std::vector<float> moved, step;
    for (float m : special)
        for (float s : steps) moved.push_back(m), step.push_back(s);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> exponent(-40.0f, 38.0f), sign(-1.0f, 1.0f);
    while (moved.size() % 8 != 0 || moved.size() < 4096) {
        moved.push_back(std::copysign(std::pow(10.0f, exponent(rng)), sign(rng)));
        step.push_back(sign(rng));
    }
    const cl::Program program = test::build_test_program(expand_kernel_source("stages/scatter_probe.cl"));
    const std::vector<float> out =
        test::run_probe(program, "round_away_probe", moved.size() / 8, 3 * moved.size(), moved, step);
    int differing = 0;
    for (size_t i = 0; i < moved.size(); ++i) {
        const float expected = out[3 * i];
        for (int width = 0; width < 2; ++width)
            if (!same(out[3 * i + 1 + width], expected) && ++differing <= 8)
                ADD_FAILURE() << "width " << (width ? 8 : 1) << ": moved " << moved[i] << " step " << step[i]
                              << " gave " << out[3 * i + 1 + width] << ", nextafter " << expected;
    }
    EXPECT_EQ(differing, 0);
}

} // namespace
} // namespace wf
