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
    // Shadow segments Embree alone finds blocked, by where the exact crossing
    // of its blocking triangle lies (classify_embree_only).
    size_t embree_past_end = 0; // at or beyond an end: Embree's rounding, not a blocker
    size_t embree_inside = 0;   // inside the segment: one our test does not report
    double fraction() const { return rays ? static_cast<double>(agree) / rays : 1.0; }
    // The share of rays that agree or where Embree's own rounding alone differs.
    double explained_fraction() const {
        return rays ? static_cast<double>(agree + embree_past_end) / rays : 1.0;
    }
};

// The relative tolerance on t.
constexpr double kTTolerance = 1e-4;

// `order` is Bvh::order: ours are BVH positions, Embree's primIDs scene triangles.
Agreement compare_closest(const ClosestHits& ours, const EmbreeHits& embree, const std::vector<uint32_t>& order);
Agreement compare_any(const AnyHits& ours, const EmbreeOcclusion& embree);

// Fills embree_past_end and embree_inside for compare_any's segments: for each
// that Embree alone finds blocked, Embree's closest hit on it, and that
// triangle's crossing recomputed in long double. `positions` are the placed
// triangles' corners, flattened(scene)'s (EmbreeHits::placed indexes them).
void classify_embree_only(Agreement& a, const std::vector<BatchRay>& segments, const AnyHits& ours,
                          const EmbreeOcclusion& theirs, const EmbreeScene& embree,
                          const std::vector<glm::vec3>& positions);

} // namespace wf::bench
