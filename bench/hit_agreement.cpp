// hit_agreement.cpp — see hit_agreement.h.
#include "hit_agreement.h"

#include <cmath>
#include <cstring>

namespace wf::bench {

Agreement compare_closest(const ClosestHits& ours, const EmbreeHits& embree, const std::vector<uint32_t>& order) {
    Agreement a;
    a.rays = ours.hits.size();
    for (size_t i = 0; i < a.rays; ++i) {
        int32_t triangle;
        std::memcpy(&triangle, &ours.hits[i].s[3], sizeof triangle);
        const bool we_hit = triangle >= 0, they_hit = embree.prim[i] != RTC_INVALID_GEOMETRY_ID;
        if (we_hit != they_hit) {
            ++(we_hit ? a.ours_only : a.embree_only);
        } else if (!we_hit) {
            ++a.agree;
        } else if (order[triangle] != embree.prim[i]) {
            ++a.other_triangle;
        } else {
            const double t = ours.hits[i].s[0], u = embree.t[i];
            ++(std::fabs(t - u) <= kTTolerance * std::fmax(std::fabs(t), std::fabs(u)) ? a.agree : a.other_t);
        }
    }
    return a;
}

Agreement compare_any(const AnyHits& ours, const EmbreeOcclusion& embree) {
    Agreement a;
    a.rays = ours.occluded.size();
    for (size_t i = 0; i < a.rays; ++i) {
        if (ours.occluded[i] == embree.occluded[i]) ++a.agree;
        else ++(ours.occluded[i] ? a.ours_only : a.embree_only);
    }
    return a;
}

} // namespace wf::bench
