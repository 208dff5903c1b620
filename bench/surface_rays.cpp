// surface_rays.cpp — triangles are drawn with the alias table the light
// choice uses, and points and directions with the kernels' own warps
// (common/sampling.h), compiled for the host.
#include "surface_rays.h"

#include <algorithm>
#include <random>

#include "base/alias_table.h"
#include "common/sampling.h"
#include "geometry/ray_offset.h"

namespace wf::bench {
namespace {

using glm::vec3;

struct SurfacePoint {
    vec3 position;
    vec3 error;  // per component, as interpolation_error bounds it
    vec3 normal; // unit geometric normal of the front face
};

class SurfaceSampler {
public:
    SurfaceSampler(const Scene& scene, uint32_t seed) : scene_(scene), rng_(seed) {
        std::vector<double> areas(scene.triangle_count());
        for (size_t t = 0; t < areas.size(); ++t) areas[t] = glm::length(edge_cross(t));
        table_ = build_alias_table(areas); // zero-area triangles are never drawn
    }

    // 24 random bits in [0, 1), the same on every standard library.
    float uniform() { return static_cast<float>(rng_() >> 8) * 0x1p-24f; }
    glm::vec2 uniform2() { return {uniform(), uniform()}; }

    SurfacePoint point() {
        const auto i = std::min(static_cast<size_t>(uniform() * table_.size()), table_.size() - 1);
        const size_t t = uniform() < table_[i].probability ? i : table_[i].alias;
        const vec3 &v0 = scene_.positions[3 * t], &v1 = scene_.positions[3 * t + 1], &v2 = scene_.positions[3 * t + 2];
        const glm::vec2 b = wf_device::sample_triangle_uniform(uniform2());
        return {wf_device::interpolate_triangle(v0, v1, v2, b.x, b.y),
                wf_device::interpolation_error(v0, v1, v2, b.x, b.y), glm::normalize(edge_cross(t))};
    }

private:
    vec3 edge_cross(size_t t) const {
        const vec3* p = &scene_.positions[3 * t];
        return glm::cross(p[1] - p[0], p[2] - p[0]);
    }

    const Scene& scene_;
    std::mt19937 rng_;
    std::vector<AliasEntry> table_;
};

} // namespace

std::vector<BatchRay> bounce_rays(const Scene& scene, uint32_t count, uint32_t seed) {
    SurfaceSampler sampler(scene, seed);
    std::vector<BatchRay> rays(count);
    for (BatchRay& ray : rays) {
        const SurfacePoint s = sampler.point();
        vec3 tangent, bitangent;
        wf_device::orthonormal_basis(s.normal, &tangent, &bitangent);
        const vec3 local = wf_device::sample_cosine_hemisphere(sampler.uniform2());
        ray.direction = local.x * tangent + local.y * bitangent + local.z * s.normal;
        ray.origin = wf_device::offset_ray_origin(s.position, s.error, s.normal, ray.direction);
    }
    return rays;
}

std::vector<BatchRay> shadow_segments(const Scene& scene, uint32_t count, uint32_t seed) {
    SurfaceSampler sampler(scene, seed);
    std::vector<BatchRay> rays(count);
    for (BatchRay& ray : rays) {
        const SurfacePoint from = sampler.point(), to = sampler.point();
        ray.origin = wf_device::offset_ray_origin(from.position, from.error, from.normal, to.position - from.position);
        ray.direction = wf_device::segment_to_surface(ray.origin, to.position, to.error, to.normal);
    }
    return rays;
}

} // namespace wf::bench
