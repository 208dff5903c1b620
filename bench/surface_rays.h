// surface_rays.h — the incoherent rays of the throughput bench, made the way a
// render's bounces make them: from points spread over the scene's surfaces by
// area, leaving with the renderer's error-bounded offset
// (kernels/geometry/ray_offset.h). Deterministic for a given seed.
#pragma once

#include <cstdint>
#include <vector>

#include "integrator/ray_batch.h"
#include "scene/scene.h"

namespace wf::bench {

// Diffuse bounces: a direction cosine-distributed about the front face's
// geometric normal, from a point just off that face.
std::vector<BatchRay> bounce_rays(const Scene& scene, uint32_t count, uint32_t seed);

// Shadow segments between two such points, offset at both ends as next-event
// estimation offsets them; the direction is the whole segment (t in (0, 1)).
std::vector<BatchRay> shadow_segments(const Scene& scene, uint32_t count, uint32_t seed);

} // namespace wf::bench
