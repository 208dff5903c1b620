// traversal_work.cpp — see traversal_work.h. Each ray runs traversal_step to
// its end, the child it is about to visit read before every step: a node
// word is a visit, a leaf word its blocks.
#include "traversal_work.h"

#include "geometry/bvh_traverse.h"

namespace wf::bench {

TraversalWork traversal_work(const DeviceSceneData& scene, const std::vector<BatchRay>& rays, bool any_hit,
                             float t_far) {
    using namespace wf_device;
    const Instance* instances = scene.instances.empty() ? nullptr : scene.instances.data();
    double nodes = 0.0, blocks = 0.0;
    for (const BatchRay& r : rays) {
        Traversal t;
        TraversalStack stack;
        traversal_start(&t, scene.nodes.data(), r.origin, r.direction, any_hit ? 1.0f : t_far);
        for (int done = 0; !done;) {
            const uint32_t child = t.child;
            if (child & WF_BVH_LEAF) {
                const uint32_t first = child & WF_BVH_FIRST_MASK;
                const uint32_t last = first + ((child & ~WF_BVH_LEAF) >> WF_BVH_COUNT_SHIFT);
                // A top-tree leaf of a two-level tree is a placement, entered, not tested.
                if (!(instances && t.instance < 0)) blocks += last / WF_BLOCK_LANES - first / WF_BLOCK_LANES + 1;
            } else {
                nodes += 1.0;
            }
            done = traversal_step(&t, &stack, scene.nodes.data(), scene.triangles.data(), any_hit ? 1 : 0, instances);
        }
    }
    const double n = rays.empty() ? 1.0 : static_cast<double>(rays.size());
    return TraversalWork{nodes / n, blocks / n};
}

} // namespace wf::bench
