// tree_cost.h — what a BVH costs a ray, by the surface area heuristic: the
// expected node visits and triangle-block tests of a ray that crosses the
// scene's box, each node and leaf weighted by its box's area over the scene
// box's (MacDonald and Booth 1990), as the builder's costs are. The bench
// reports it beside the build's time and bytes
// (DeviceSceneData::traversal_bytes), so that a tree change shows what it did
// to the tree before what it did to the speed.
#pragma once

#include "bvh/bvh_builder.h"

namespace wf::bench {

struct TreeCost {
    double node_visits = 0.0; // 8-wide node visits a ray, node 0's own not counted
    double block_tests = 0.0; // four-triangle block tests a ray
};

TreeCost tree_cost(const Bvh& bvh);

// The blocks of four triangles a leaf's child word spans, the ones its test
// loads: first to last, inclusive.
struct LeafBlocks {
    uint32_t first = 0, last = 0;
    uint32_t count() const { return last - first + 1; }
};
LeafBlocks leaf_blocks(uint32_t leaf);

} // namespace wf::bench
