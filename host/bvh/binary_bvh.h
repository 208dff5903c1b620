// binary_bvh.h — the binary BVH of a scene's triangles, built by binned SAH:
// the tree that host/bvh/bvh_builder.h collapses into the 8-wide layout the
// kernels traverse.
//
// Promises: a binary tree rooted at node 0 whose two children always sit side
// by side; every triangle in exactly one leaf, of one triangle save where
// SAH finds no split or the depth bound stops it (then at most 4); every
// box holding its children's boxes and its triangles' corners; at most
// kMaxBinaryDepth levels. Built single-threaded; deterministic.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace wf {

// Leaves fill the float4 lanes of the triangle test.
constexpr uint32_t kMaxLeafSize = 4;
// The root is level 1; see host/bvh/bvh_builder.cpp for what this bounds.
constexpr int kMaxBinaryDepth = 63;

struct BinaryBvhNode {
    Bounds bounds;
    uint32_t first = 0; // interior: children at first and first + 1; leaf: its first BVH position
    uint32_t count = 0; // triangles in a leaf; 0 for an interior node
};

struct BinaryBvh {
    std::vector<BinaryBvhNode> nodes; // root at 0
    std::vector<uint32_t> order;      // order[i] = index of the scene triangle placed at BVH position i
    int depth = 0;                    // deepest level (root = 1)
};

// positions: three corners per triangle (world space). Zero-area triangles are
// kept. Throws std::invalid_argument when there are no triangles, when the
// count of corners is not a multiple of 3, when a corner is not finite, or when
// there are more triangles than a leaf's child word can index (2^28).
BinaryBvh build_binary_bvh(const std::vector<glm::vec3>& positions);

// The same over boxes (the placements of a two-level tree,
// host/bvh/instance_bvh.h), one a leaf, order indexing `boxes`; throws where
// there are none or one is empty or not finite.
BinaryBvh build_binary_bvh(const std::vector<Bounds>& boxes);

// Four-triangle tests that n triangles take, in leaves of at most max_leaf
// (a two-level tree's top prices a placement as one such test): SAH's cost
// of a leaf, in the unit of the builders' costs.
double leaf_tests(uint32_t n, uint32_t max_leaf);

// Half the surface area, which SAH weighs by; in double, where the products of
// float extents cannot overflow. 0 for an empty box.
double half_area(const Bounds& b);

} // namespace wf
