// embree_tracer.h — the reference the throughput bench measures against:
// Embree 3 over the scene's world-space triangles, traced one ray per call
// (rtcIntersect1, rtcOccluded1) or in packets of 8 (rtcIntersect8) on a given
// number of std::threads, each taking one static chunk of the rays.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "integrator/ray_batch.h"

namespace wf::bench {

struct EmbreeHits {
    std::vector<float> t;       // per ray; infinity on a miss
    std::vector<uint32_t> prim; // the scene triangle hit, RTC_INVALID_GEOMETRY_ID on a miss
    double seconds = 0.0;       // wall time of the tracing threads
};

struct EmbreeOcclusion {
    std::vector<uint8_t> occluded;
    double seconds = 0.0;
};

class EmbreeScene {
public:
    // positions: three corners per triangle, in the scene's order (primID = triangle).
    EmbreeScene(const std::vector<glm::vec3>& positions, unsigned threads);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // Closest hits, t in [0, t_far].
    EmbreeHits intersect1(const std::vector<BatchRay>& rays, float t_far = INFINITY) const;
    // The same, eight consecutive rays per call.
    EmbreeHits intersect8(const std::vector<BatchRay>& rays) const;
    // Any hit along each ray's direction taken as the whole segment, t in [0, 1].
    EmbreeOcclusion occluded1(const std::vector<BatchRay>& rays) const;

    // Wall time of the scene's build (rtcCommitScene) on the threads given.
    double build_seconds() const { return build_seconds_; }

private:
    unsigned threads_;
    double build_seconds_ = 0.0;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
};

} // namespace wf::bench
