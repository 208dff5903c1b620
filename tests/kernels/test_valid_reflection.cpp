// test_valid_reflection.cpp — kernels/materials/valid_reflection.h compiled
// for the host: over random geometric normals, views and mapped normals, the
// normal it returns is unit, mirrors the view above the surface by the height
// it promises, and is the given normal, bit for bit, wherever that one already
// did so.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "materials/valid_reflection.h"

namespace wf {
namespace {

using wf_device::float3;

float3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        const float3 v(g(rng), g(rng), g(rng));
        const float l = std::sqrt(wf_device::dot(v, v));
        if (l > 1e-3f) return v / l;
    }
}

TEST(ValidReflection, MirrorsTheViewAboveTheSurfaceAndLeavesGoodNormalsAlone) {
    std::mt19937 rng(5);
    int bent = 0, kept = 0;
    for (int k = 0; k < 200000; ++k) {
        const float3 ng = random_unit(rng);
        float3 v = random_unit(rng), n = random_unit(rng);
        if (wf_device::dot(v, ng) < 0.0f) v = -v;
        if (wf_device::dot(n, ng) < 0.0f) n = -n;
        if (wf_device::dot(v, ng) < 1e-4f) continue;
        const float height = std::min(0.9f * wf_device::dot(v, ng), 0.01f);
        const bool valid = wf_device::dot(2.0f * wf_device::dot(n, v) * n - v, ng) >= height;
        const float3 m = wf_device::valid_reflection_normal(ng, v, n);
        ASSERT_NEAR(wf_device::dot(m, m), 1.0f, 1e-5f);
        const float r_height = wf_device::dot(2.0f * wf_device::dot(m, v) * m - v, ng);
        ASSERT_GE(r_height, height - 2e-4f) << "k " << k;
        if (valid) {
            ASSERT_TRUE(m.x == n.x && m.y == n.y && m.z == n.z) << "k " << k;
            ++kept;
        } else {
            ASSERT_LE(r_height, height + 2e-4f) << "lifted further than needed, k " << k;
            ++bent;
        }
    }
    EXPECT_GT(bent, 10000);
    EXPECT_GT(kept, 10000);
}

} // namespace
} // namespace wf
