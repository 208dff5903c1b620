// bvh_builder.h — the bounding volume hierarchy over a scene's triangles, in
// the layout the kernels traverse (kernels/geometry/bvh_traverse.h).
//
// Promises: a binary tree rooted at node 0 whose two children always sit side
// by side; every triangle in exactly one leaf; every box holding its
// children's boxes and its triangles' corners; depth below the traversal's
// stack size. Built single-threaded by binned SAH; deterministic.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "wavefront/scene_types.h"

namespace wf {

struct Bvh {
    std::vector<BvhNode> nodes;  // root at 0
    std::vector<uint32_t> order; // order[i] = index of the scene triangle placed at BVH position i
    int depth = 0;               // deepest level (root = 1)
};

// positions: three corners per triangle (world space). Zero-area triangles are
// kept. Throws std::invalid_argument when there are no triangles, when the
// count of corners is not a multiple of 3, when a corner is not finite, or when
// there are more triangles than an int32_t can index.
Bvh build_bvh(const std::vector<glm::vec3>& positions);

} // namespace wf
