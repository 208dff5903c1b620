// leaf_blocks.h — places a BVH's leaves in blocks of four BVH positions
// (TriangleBlock, include/wavefront/scene_types.h), the unit the leaf test
// loads a row at a time (kernels/geometry/bvh_traverse.h).
//
// Promises: a leaf of four or more triangles starts a block; a smaller one
// lies within one block, sharing it with other small leaves or with the tail
// of a larger one where there is room (best fit), so few lanes go unused.
// Each leaf keeps its triangles, in their order; each lane no leaf uses is
// kNoTriangle in `order`, whose size becomes a multiple of four. Deterministic.
#pragma once

#include <cstdint>

#include "bvh/bvh_builder.h"

namespace wf {

// Rewrites the leaves' child words and `order` of a BVH whose leaves are
// runs of `order` (as the collapse leaves them).
void place_leaves_in_blocks(Bvh& bvh);

} // namespace wf
