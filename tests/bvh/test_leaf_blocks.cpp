// test_leaf_blocks.cpp — the placement of leaves in blocks of four
// (host/bvh/leaf_blocks.h) on a hand-made tree whose answer is worked out by
// hand; the builder's own trees are checked in test_bvh.cpp.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "bvh/leaf_blocks.h"

namespace wf {
namespace {

uint32_t leaf(uint32_t first, uint32_t count) { return WF_BVH_LEAF | (count - 1) << WF_BVH_COUNT_SHIFT | first; }
uint32_t first_of(uint32_t child) { return child & WF_BVH_FIRST_MASK; }
uint32_t count_of(uint32_t child) { return ((child & ~WF_BVH_LEAF) >> WF_BVH_COUNT_SHIFT) + 1; }

TEST(LeafBlocks, SmallLeavesFillTheGapsBestFit) {
    // Leaves of 2, 3, 1, 2, 5, 3, 1 triangles as runs of 0..16, in two nodes.
    const std::vector<uint32_t> sizes = {2, 3, 1, 2, 5, 3, 1};
    Bvh bvh;
    bvh.nodes.resize(2);
    uint32_t run = 0;
    for (size_t i = 0; i < sizes.size(); ++i) {
        bvh.nodes[i < 4 ? 0 : 1].child[i % 4] = leaf(run, sizes[i]);
        run += sizes[i];
    }
    for (uint32_t t = 0; t < run; ++t) bvh.order.push_back(100 + t);
    place_leaves_in_blocks(bvh);

    // 2 opens block 0, 3 block 1; the 1 fills block 1 (best fit: the fuller
    // block, not block 0), the next 2 block 0; 5 takes block 2 and a lane of
    // 3, where the next 3 fits; the last 1 opens block 4.
    const std::vector<uint32_t> expected_first = {0, 4, 7, 2, 8, 13, 16};
    run = 0;
    for (size_t i = 0; i < sizes.size(); ++i) {
        const uint32_t child = bvh.nodes[i < 4 ? 0 : 1].child[i % 4];
        ASSERT_TRUE(child & WF_BVH_LEAF);
        EXPECT_EQ(count_of(child), sizes[i]) << "leaf " << i;
        EXPECT_EQ(first_of(child), expected_first[i]) << "leaf " << i;
        for (uint32_t k = 0; k < sizes[i]; ++k)
            EXPECT_EQ(bvh.order[first_of(child) + k], 100 + run + k) << "leaf " << i << " keeps its run";
        run += sizes[i];
    }
    ASSERT_EQ(bvh.order.size(), 20u);
    for (uint32_t i : {17u, 18u, 19u}) EXPECT_EQ(bvh.order[i], kNoTriangle) << "position " << i;
}

} // namespace
} // namespace wf
