// traversal_work.cpp — see traversal_work.h. Each ray runs traversal_step to
// its end, the child it is about to visit read before every step: a node
// word is a visit, a leaf word its blocks (leaf_blocks, tree_cost.h), less,
// for an any-hit ray, the blocks after the one holding the hit it stops at.
#include "traversal_work.h"

#include <cmath>

#include "geometry/bvh_traverse.h"
#include "tree_cost.h"

namespace wf::bench {

TraversalWork traversal_work(const DeviceSceneData& scene, const std::vector<BatchRay>& rays, bool any_hit) {
    using namespace wf_device;
    const Instance* instances = scene.instances.empty() ? nullptr : scene.instances.data();
    double nodes = 0.0, blocks = 0.0;
    for (const BatchRay& r : rays) {
        Traversal t;
        TraversalStack stack;
        traversal_start(&t, scene.nodes.data(), r.origin, r.direction, any_hit ? 1.0f : INFINITY);
        uint32_t leaf_last_block = 0u; // of the last leaf tested
        for (int done = 0; !done;) {
            const uint32_t child = t.child;
            if (!(child & WF_BVH_LEAF)) {
                nodes += 1.0;
            } else if (!(instances && t.instance < 0)) { // in a two-level tree's top, a placement: entered
                const LeafBlocks leaf = leaf_blocks(child);
                blocks += leaf.count();
                leaf_last_block = leaf.last;
            }
            done = traversal_step(&t, &stack, scene.nodes.data(), scene.triangles.data(), any_hit ? 1 : 0, instances);
        }
        // An any-hit ray stops inside the leaf of its hit (leaf_hits), untested blocks after it.
        if (any_hit && t.selection.closest.triangle >= 0)
            blocks -= leaf_last_block - static_cast<uint32_t>(t.selection.closest.triangle) / WF_BLOCK_LANES;
    }
    const double n = rays.empty() ? 1.0 : static_cast<double>(rays.size());
    return TraversalWork{nodes / n, blocks / n};
}

} // namespace wf::bench
