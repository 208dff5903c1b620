// test_pool_size.cpp — how many paths a render keeps in flight: the request
// or the default, never more than the pixels (each slot owns whole pixels),
// and by default no more than the device's memory holds.
#include <gtest/gtest.h>

#include "integrator/path_integrator.h"
#include "integrator/path_pool.h"

namespace wf {
namespace {

TEST(PoolSize, AtMostThePixelCount) {
    std::string note;
    EXPECT_EQ(choose_pool_size(0, default_pool_size("gpu", 132, Integrator::Wavefront), 1u << 22, &note), 132u * 8192);
    EXPECT_EQ(default_pool_size("gpu", 20, Integrator::Megakernel), 1u << 18); // at least 2^18
    EXPECT_EQ(choose_pool_size(0, default_pool_size("cpu", 2, Integrator::Wavefront), 1u << 20, &note), 1u << 15);
    EXPECT_EQ(choose_pool_size(0, default_pool_size("cpu", 2, Integrator::Wavefront), 1000, &note), 1000u);
    EXPECT_EQ(default_pool_size("cpu", 64, Integrator::Megakernel), 1u << 18);
    EXPECT_TRUE(note.empty());
    EXPECT_EQ(choose_pool_size(5000, default_pool_size("cpu", 2, Integrator::Wavefront), 1200, &note), 1200u);
    EXPECT_NE(note.find("capped at the pixel count"), std::string::npos);
}

TEST(PoolSize, TheDefaultShrinksToWhatTheDeviceHolds) {
    const size_t per_path = PathPool::bytes_per_path(false);
    const size_t gib = size_t{1} << 30;
    EXPECT_EQ(pool_that_fits(1u << 18, 8 * gib, 2 * gib, gib, false), 1u << 18); // room to spare
    // 100 MiB left beside the scene: half of it holds this many paths.
    const size_t left = 100u << 20;
    EXPECT_EQ(pool_that_fits(1u << 20, gib + left, gib, gib, false), (left / 2) / per_path);
    // The largest per-path allocation: the queue buffer's 5 indices a path, or the shade records where there are.
    EXPECT_EQ(pool_that_fits(1u << 20, 8 * gib, 5 * 4 * 1000, 0, false), 1000u);
    EXPECT_EQ(pool_that_fits(1u << 20, 8 * gib, PathPool::shade_record_bytes_per_path() * 1000, 0, true), 1000u);
    EXPECT_EQ(pool_that_fits(1u << 20, gib + left, gib, gib, true), (left / 2) / PathPool::bytes_per_path(true));
    EXPECT_EQ(pool_that_fits(1u << 20, gib, gib, 2 * gib, false), 0u); // nothing left
}

} // namespace
} // namespace wf
