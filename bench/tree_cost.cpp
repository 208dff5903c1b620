// tree_cost.cpp — see tree_cost.h.
#include "tree_cost.h"

#include "bvh/binary_bvh.h"
#include "wavefront/scene_types.h"

namespace wf::bench {
namespace {

// Half the surface area of slot `slot`'s box, as the builder weighs it.
double slot_half_area(const BvhNode& node, int slot) {
    Bounds b;
    for (int k = 0; k < 3; ++k) {
        b.lo[k] = node.bounds[2 * k][slot];
        b.hi[k] = node.bounds[2 * k + 1][slot];
    }
    return half_area(b);
}

} // namespace

TreeCost tree_cost(const Bvh& bvh) {
    TreeCost c;
    const double scene = slot_half_area(bvh.nodes[0], 0);
    if (!(scene > 0.0)) return c; // a flat scene: no ray crosses its box's area
    for (const BvhNode& node : bvh.nodes)
        for (int slot = 0; slot < WF_BVH_WIDTH; ++slot) {
            const uint32_t child = node.child[slot];
            if (child == 0u) continue;
            const double p = slot_half_area(node, slot) / scene; // the chance a ray through the scene box meets it
            if (!(child & WF_BVH_LEAF)) {
                c.node_visits += p;
                continue;
            }
            c.block_tests += p * leaf_blocks(child).count();
        }
    return c;
}

LeafBlocks leaf_blocks(uint32_t leaf) {
    const uint32_t first = leaf & WF_BVH_FIRST_MASK;
    const uint32_t last = first + ((leaf & ~WF_BVH_LEAF) >> WF_BVH_COUNT_SHIFT);
    return LeafBlocks{first / WF_BLOCK_LANES, last / WF_BLOCK_LANES};
}

} // namespace wf::bench
