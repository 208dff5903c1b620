// bvh_builder.h — the bounding volume hierarchy over a scene's triangles, in
// the layout the kernels traverse (kernels/geometry/bvh_traverse.h,
// include/wavefront/scene_types.h): the binned-SAH binary tree of
// host/bvh/binary_bvh.h collapsed into 8-wide nodes, the collapse of least
// SAH cost (below) of that binary tree, save where traversal's stack bound
// forbids it (bvh_builder.cpp).
//
// Promises: node 0 has one slot, the scene's box over the top of the tree;
// every other node is the child of exactly one node before it, its children
// in slots of decreasing area; every triangle
// in exactly one leaf, a run of one to eight consecutive BVH positions, placed
// in blocks of four as host/bvh/leaf_blocks.h says; every
// child box holding its children's boxes and its triangles' corners, and every
// unused slot's box empty, its child word 0; traversal's stack never fuller
// than WF_BVH_STACK_SIZE. Deterministic.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "wavefront/scene_types.h"

namespace wf {

// The collapse's price of a node visit, in four-triangle tests (the unit of
// leaf_tests, host/bvh/binary_bvh.h): it builds the tree of least SAH cost,
// each node's box area times this plus each leaf's times its tests.
constexpr double kNodeCost = 1.0;
// The most triangles in one leaf: what its child word can count.
constexpr uint32_t kMaxLeafRun = (~WF_BVH_LEAF >> WF_BVH_COUNT_SHIFT) + 1;

// The mark in Bvh::order of a block's lane that no leaf uses.
constexpr uint32_t kNoTriangle = 0xffffffffu;

struct Bvh {
    std::vector<BvhNode> nodes;  // node 0 holds the scene's box over the top of the tree
    std::vector<uint32_t> order; // order[i] = the scene triangle at BVH position i, or kNoTriangle
    int depth = 0;               // deepest level of nodes (root = 1)
    // A two-level tree's placements (host/bvh/instance_bvh.h), which its top
    // tree's leaves index; empty for a tree of world-space triangles.
    std::vector<Instance> instances;
};

// positions: three corners per triangle (world space); throws as
// build_binary_bvh (host/bvh/binary_bvh.h) does.
Bvh build_bvh(const std::vector<glm::vec3>& positions);

// The same tree over boxes, as a two-level tree's top (instance_bvh.h): each
// leaf one box, a position of `order`, which indexes `boxes`; no blocks.
Bvh build_box_bvh(const std::vector<Bounds>& boxes);

} // namespace wf
