// test_ray_offset.cpp — a ray spawned by geometry/ray_offset.h never meets the
// triangle it leaves (1,200,000 rays), and a shadow segment between two
// triangles meets neither (500,000 segments), whatever the triangle's size
// (1e-6 to 1e6), place (up to 1e7 from the origin, or around it) and shape
// (long and thin, in an axis plane), and however close to the plane the ray
// leaves (half of them within 1e-3 of it). The triangle test is the shared
// intersect_triangle, as the kernels run it.
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "geometry/ray_offset.h"
#include "geometry/triangle_intersect.h"
#include "support/test_support.h"

namespace wf {
namespace {

using glm::dvec3;
using glm::vec3;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

using Corners = std::array<vec3, 3>;

// A point on a triangle as the renderer makes one: interpolated, with its error
// bound and the float geometric normal (cross product of the edges).
struct SurfacePoint {
    Corners corners;
    vec3 position;
    vec3 error;
    vec3 normal;      // unit, from float arithmetic as in kernels/stages/shade.h
    dvec3 true_normal; // unit, of the float corners, in double
};

class Generator {
public:
    explicit Generator(uint32_t seed) : rng_(seed) {}

    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng_); }
    float log_uniform(float lo_exp, float hi_exp) { return std::pow(10.0f, uniform(lo_exp, hi_exp)); }
    vec3 unit() {
        std::normal_distribution<float> n;
        return glm::normalize(vec3(n(rng_), n(rng_), n(rng_)));
    }

    // A triangle of one of four kinds; its size is 10^[-6, 6] and, where it is
    // not around the origin, each coordinate of its centre is 0 or ±10^[-3, 7].
    Corners triangle() {
        const float size = log_uniform(-6.0f, 6.0f);
        vec3 center(0.0f);
        for (int k = 0; k < 3; ++k) {
            const float sign = uniform(0.0f, 1.0f) < 0.5f ? -1.0f : 1.0f;
            if (uniform(0.0f, 1.0f) < 0.9f) center[k] = sign * log_uniform(-3.0f, 7.0f);
        }
        switch (std::uniform_int_distribution<int>(0, 3)(rng_)) {
        case 0: // ordinary
            return {center + size * unit(), center + size * unit(), center + size * unit()};
        case 1: { // long and thin: aspect 10 to 10^4
            const vec3 b = center + size * unit();
            const vec3 side = log_uniform(-4.0f, -1.0f) * size * unit();
            return {center, b, center + uniform(0.0f, 1.0f) * (b - center) + side};
        }
        case 2: { // around the origin, often containing it
            const vec3 near = uniform(0.0f, 1.0f) * size * unit();
            return {near + size * unit(), near + size * unit(), near + size * unit()};
        }
        default: { // in an axis plane, as walls and floors are
            Corners c = {center + size * unit(), center + size * unit(), center + size * unit()};
            const int axis = std::uniform_int_distribution<int>(0, 2)(rng_);
            for (vec3& v : c) v[axis] = center[axis];
            return c;
        }
        }
    }

    // A random point of a random usable triangle: its corners, once rounded to
    // float, still span a triangle at least 128 ulps across whose float normal
    // is within 1e-5 of the true one (finer triangles have no normal to offset
    // along). A tenth of the points lie on an edge, a tenth on a corner.
    SurfacePoint point() {
        for (;;) {
            SurfacePoint s;
            s.corners = triangle();
            const auto [v0, v1, v2] = s.corners;
            const float reach = glm::max(glm::max(glm::length(v0), glm::length(v1)), glm::length(v2));
            const float extent = glm::max(glm::length(v1 - v0), glm::length(v2 - v0));
            const vec3 cross_edges = glm::cross(v1 - v0, v2 - v0);
            const float area2 = glm::length(cross_edges);
            const dvec3 exact = glm::cross(dvec3(v1) - dvec3(v0), dvec3(v2) - dvec3(v0));
            if (!(area2 > 0.0f) || !std::isfinite(area2) || extent < 0x1p-17f * reach) continue;
            s.normal = cross_edges / area2;
            s.true_normal = glm::normalize(exact);
            if (glm::length(dvec3(s.normal) - s.true_normal) > 1e-5) continue;

            float b1 = uniform(0.0f, 1.0f), b2 = uniform(0.0f, 1.0f);
            if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
            const float kind = uniform(0.0f, 1.0f);
            if (kind < 0.1f) b2 = 0.0f;                         // on an edge
            else if (kind < 0.2f) b1 = uniform(0.0f, 1.0f) < 0.5f ? 1.0f : 0.0f, b2 = 0.0f; // a corner
            s.position = wf_device::interpolate_triangle(v0, v1, v2, b1, b2);
            s.error = wf_device::interpolation_error(v0, v1, v2, b1, b2);
            return s;
        }
    }

    // A unit direction on the side `side` (±1) of the surface: uniform on the
    // hemisphere, or, every other time, grazing at 1e-5 to 1e-3 from the plane;
    // redrawn while the float normal would put it on the other side.
    vec3 leaving(const SurfacePoint& s, float side) {
        for (;;) {
            const dvec3 n = double(side) * s.true_normal;
            vec3 w = unit();
            if (uniform(0.0f, 1.0f) < 0.5f) {
                const dvec3 tangent = glm::normalize(glm::cross(n, dvec3(unit())));
                w = vec3(glm::normalize(tangent + double(log_uniform(-5.0f, -3.0f)) * n));
            } else if (glm::dot(dvec3(w), n) < 0.0) {
                w = -w;
            }
            if (glm::dot(dvec3(w), n) > 0.0 && side * glm::dot(s.normal, w) > 0.0f) return w;
        }
    }

private:
    std::mt19937 rng_;
};

bool hits(const Corners& c, vec3 origin, vec3 direction, float t_max) {
    const wf_device::WatertightRay ray = wf_device::watertight_ray(origin, direction);
    wf_device::TriangleHit hit;
    return wf_device::intersect_triangle(&ray, c[0], c[1], c[2], t_max, &hit) != 0;
}

TEST(RayOffset, SpawnedRaysNeverHitTheirOwnTriangle) {
    Generator g(17);
    const int rays = 1'200'000;
    int rehits = 0, grazing = 0;
    for (int i = 0; i < rays; ++i) {
        const SurfacePoint s = g.point();
        const float side = i % 2 ? 1.0f : -1.0f; // either face may be the one hit
        const vec3 w = g.leaving(s, side);
        grazing += std::abs(glm::dot(s.normal, w)) < 1e-3f;
        const vec3 origin = wf_device::offset_ray_origin(s.position, s.error, s.normal, w);
        if (hits(s.corners, origin, w, kInfinity) && ++rehits <= 5)
            ADD_FAILURE() << "re-hit from (" << s.position.x << ", " << s.position.y << ", " << s.position.z
                          << ") along (" << w.x << ", " << w.y << ", " << w.z << ")";
    }
    test::report_measured(std::to_string(rehits) + " re-hits of " + std::to_string(rays) + " rays, " +
                          std::to_string(grazing) + " of them within 0.06° of the surface");
    EXPECT_EQ(rehits, 0) << "of " << rays << " rays";
    EXPECT_GT(grazing, rays / 3);
}

// How far q lies in front of the triangle's plane, in double, where the front
// is the side that the float normal n is on.
double in_front(const SurfacePoint& s, vec3 n, vec3 q) {
    const dvec3 front = glm::dot(dvec3(n), s.true_normal) > 0.0 ? s.true_normal : -s.true_normal;
    return glm::dot(front, dvec3(q) - dvec3(s.corners[0]));
}

TEST(RayOffset, ShadowSegmentsMeetNeitherEnd) {
    // A receiver and a light point on two random triangles, each facing the
    // other. The segment crosses each triangle's plane only at its own end, so
    // any hit of either triangle with t in (0, 1) is the offset failing.
    Generator g(23);
    const int segments = 500'000;
    int blocked = 0, unresolved = 0;
    for (int i = 0; i < segments; ++i) {
        const SurfacePoint from = g.point(), to = g.point();
        const vec3 along = to.position - from.position;
        const vec3 n_from = glm::dot(from.normal, along) >= 0.0f ? from.normal : -from.normal;
        const vec3 n_to = glm::dot(to.normal, along) <= 0.0f ? to.normal : -to.normal;
        const vec3 origin = wf_device::offset_ray_origin(from.position, from.error, n_from, along);
        const vec3 segment = wf_device::segment_to_surface(origin, to.position, to.error, n_to);
        // Each end must lie in front of the other's plane beyond doubt: pairs
        // closer to that plane than the rounding of their points are redrawn.
        if (in_front(from, n_from, origin + segment) <= 0.0 || in_front(to, n_to, origin) <= 0.0) {
            ++unresolved;
            --i;
            continue;
        }
        if ((hits(from.corners, origin, segment, 1.0f) || hits(to.corners, origin, segment, 1.0f)) &&
            ++blocked <= 5)
            ADD_FAILURE() << "blocked from (" << from.position.x << ", " << from.position.y << ", "
                          << from.position.z << ") to (" << to.position.x << ", " << to.position.y << ", "
                          << to.position.z << ")";
    }
    test::report_measured(std::to_string(blocked) + " of " + std::to_string(segments) +
                          " shadow segments blocked by the surfaces at their ends");
    EXPECT_EQ(blocked, 0) << "of " << segments << " segments";
    EXPECT_LT(unresolved, segments / 2);
}

} // namespace
} // namespace wf
