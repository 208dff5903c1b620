// leaf_blocks.cpp — see leaf_blocks.h. Leaves are placed in the order the
// tree holds them (nodes in depth-first order), so siblings tend to share
// blocks and cache lines.
#include "bvh/leaf_blocks.h"

#include <array>
#include <stdexcept>
#include <vector>

#include "wavefront/scene_types.h"

namespace wf {

void place_leaves_in_blocks(Bvh& bvh) {
    const std::vector<uint32_t> runs = std::move(bvh.order);
    std::vector<uint32_t>& order = bvh.order;
    order.clear();
    order.reserve(runs.size() + runs.size() / 4);
    // open[u]: blocks whose first u lanes are taken and the rest free, most recent last.
    std::array<std::vector<uint32_t>, WF_BLOCK_LANES> open;
    for (size_t n = 0; n < bvh.nodes.size(); ++n) { // node 0 too: a tree of one leaf
        for (uint32_t& child : bvh.nodes[n].child) {
            if (!(child & WF_BVH_LEAF)) continue;
            const uint32_t first = child & WF_BVH_FIRST_MASK;
            const uint32_t count = ((child & ~WF_BVH_LEAF) >> WF_BVH_COUNT_SHIFT) + 1u;
            uint32_t taken = 0; // lanes taken in the block it joins; 0: a new block
            if (count < WF_BLOCK_LANES)
                for (uint32_t u = WF_BLOCK_LANES - count; u > 0 && taken == 0; --u)
                    if (!open[u].empty()) taken = u;
            uint32_t at;
            if (taken > 0) {
                const uint32_t block = open[taken].back();
                open[taken].pop_back();
                at = block * WF_BLOCK_LANES + taken;
            } else {
                if (order.size() + WF_BVH_WIDTH > size_t{WF_BVH_FIRST_MASK} + 1)
                    throw std::invalid_argument("too many triangles for the BVH's leaf words (2^28 positions)");
                at = static_cast<uint32_t>(order.size());
                order.resize(order.size() + (count + WF_BLOCK_LANES - 1) / WF_BLOCK_LANES * WF_BLOCK_LANES,
                             kNoTriangle);
            }
            for (uint32_t i = 0; i < count; ++i) order[at + i] = runs[first + i];
            const uint32_t end = at + count, used = end % WF_BLOCK_LANES;
            if (used != 0) open[used].push_back(end / WF_BLOCK_LANES);
            child = WF_BVH_LEAF | (count - 1) << WF_BVH_COUNT_SHIFT | at;
        }
    }
}

} // namespace wf
