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

namespace {

// The ray parameter at which the line origin + t direction crosses the plane
// of triangle p, if it crosses inside the triangle: Moller and Trumbore in
// long double, far finer than the floats it starts from.
bool exact_crossing(const BatchRay& r, const glm::vec3* p, long double* t) {
    using L = long double;
    L e1[3], e2[3], s[3], d[3];
    for (int k = 0; k < 3; ++k) {
        e1[k] = L{p[1][k]} - L{p[0][k]};
        e2[k] = L{p[2][k]} - L{p[0][k]};
        s[k] = L{r.origin[k]} - L{p[0][k]};
        d[k] = r.direction[k];
    }
    const auto cross = [](const L* a, const L* b, L* c) {
        c[0] = a[1] * b[2] - a[2] * b[1];
        c[1] = a[2] * b[0] - a[0] * b[2];
        c[2] = a[0] * b[1] - a[1] * b[0];
    };
    const auto dot = [](const L* a, const L* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    L pv[3], qv[3];
    cross(d, e2, pv);
    cross(s, e1, qv);
    const L det = dot(e1, pv);
    if (det == 0) return false;
    const L u = dot(s, pv) / det, v = dot(d, qv) / det;
    *t = dot(e2, qv) / det;
    return u >= 0 && v >= 0 && u + v <= 1;
}

} // namespace

void classify_embree_only(Agreement& a, const std::vector<BatchRay>& segments, const AnyHits& ours,
                          const EmbreeOcclusion& theirs, const EmbreeScene& embree,
                          const std::vector<glm::vec3>& positions) {
    std::vector<BatchRay> only;
    for (size_t i = 0; i < segments.size(); ++i)
        if (theirs.occluded[i] && !ours.occluded[i]) only.push_back(segments[i]);
    const EmbreeHits hits = embree.intersect1(only, 1.0f);
    for (size_t i = 0; i < only.size(); ++i) {
        long double t = 0;
        const bool inside = hits.placed[i] != RTC_INVALID_GEOMETRY_ID &&
                            exact_crossing(only[i], &positions[3 * size_t{hits.placed[i]}], &t) && t > 0 && t < 1;
        ++(inside ? a.embree_inside : a.embree_past_end);
    }
}

} // namespace wf::bench
