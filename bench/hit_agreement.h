// hit_agreement.h — whether our kernels and Embree found the same thing for
// each ray: the bench's check that both traced the same rays through the same
// triangles, so that their speeds can be compared.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "embree_tracer.h"
#include "integrator/ray_batch.h"

namespace wf::bench {

struct Agreement {
    size_t rays = 0;
    size_t agree = 0;
    size_t ours_only = 0;      // we found a hit (or a blocked segment), Embree none
    size_t embree_only = 0;    // the other way round
    size_t other_triangle = 0; // both hit, different triangles
    size_t other_t = 0;        // the same triangle, t apart by more than the tolerance
    double fraction() const { return rays ? static_cast<double>(agree) / rays : 1.0; }
};

// The relative tolerance on t.
constexpr double kTTolerance = 1e-4;

// `order` is Bvh::order: ours are BVH positions, Embree's primIDs scene triangles.
Agreement compare_closest(const ClosestHits& ours, const EmbreeHits& embree, const std::vector<uint32_t>& order);
Agreement compare_any(const AnyHits& ours, const EmbreeOcclusion& embree);

} // namespace wf::bench
