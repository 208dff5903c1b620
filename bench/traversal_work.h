// traversal_work.h — what a set of rays costs the traversal, counted: the
// 8-wide node visits and the four-triangle block tests each ray makes, by a
// CPU's traversal (kernels/geometry/bvh_traverse.h, compiled for the host and
// stepped one visit at a time). Counts, not timings: a tree or order change
// shows what it saved before a shared machine's timings can; beside the SAH
// estimate (tree_cost.h), which prices a ray through the whole scene box
// rather than the set's own rays. Two limits: the host's traversal takes every
// hit (no alpha masks), and a GPU's, which tests one triangle at a time and
// may walk the tree again, counts its own way.
#pragma once

#include <vector>

#include "device/device_scene.h"
#include "integrator/ray_batch.h"

namespace wf::bench {

struct TraversalWork {
    // A ray's visits of interior nodes; node 0, which only holds the scene's
    // box, and a placement's root, which holds its mesh's, are not visited.
    double node_visits = 0.0;
    // A ray's block tests; an any-hit ray's last leaf counts up to the block
    // of its hit. A placement's leaf in a two-level tree's top holds no blocks.
    double block_tests = 0.0;
};

// Closest-hit queries with t in (0, infinity), or any-hit ones over each
// ray's segment (t in (0, 1)), as the bench's sets trace them.
TraversalWork traversal_work(const DeviceSceneData& scene, const std::vector<BatchRay>& rays, bool any_hit);

} // namespace wf::bench
