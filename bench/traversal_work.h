// traversal_work.h — what a set of rays costs the traversal, counted: the
// 8-wide node visits and the four-triangle block tests each ray makes, by the
// very traversal the CPU's kernels run (kernels/geometry/bvh_traverse.h,
// compiled for the host and stepped one visit at a time). Exact and free of
// timing noise, so that a tree or order change shows what it saved before a
// shared machine's timings can; beside the SAH estimate (tree_cost.h), which
// prices a ray through the whole scene box rather than the set's own rays.
#pragma once

#include <vector>

#include "device/device_scene.h"
#include "integrator/ray_batch.h"

namespace wf::bench {

struct TraversalWork {
    double node_visits = 0.0; // a ray, node 0's own not counted
    double block_tests = 0.0; // a ray: the blocks of every leaf visited (an any-hit ray may stop inside its last)
};

// Closest-hit queries with t in (0, t_far), or any-hit ones over each ray's
// segment (t in (0, 1)), as the bench's sets trace them.
TraversalWork traversal_work(const DeviceSceneData& scene, const std::vector<BatchRay>& rays, bool any_hit,
                             float t_far = INFINITY);

} // namespace wf::bench
