// embree_tracer.h — the reference the throughput bench measures against:
// Embree 3 over the scene's triangles, its shared meshes as Embree's own
// instances (a scene each, placed by RTC_GEOMETRY_TYPE_INSTANCE), traced one
// ray per call (rtcIntersect1, rtcOccluded1) or in packets of 8
// (rtcIntersect8) on a given number of std::threads, each taking one static
// chunk of the rays. Built either as Embree is by default, or in its robust
// mode (RTC_SCENE_FLAG_ROBUST), whose test, like ours, is meant to let no ray
// through the edge two triangles share.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "integrator/ray_batch.h"
#include "scene/scene.h"

namespace wf::bench {

struct EmbreeHits {
    std::vector<float> t;       // per ray; infinity on a miss
    std::vector<uint32_t> prim; // the scene triangle hit, RTC_INVALID_GEOMETRY_ID on a miss
    // The triangle as placed: its index in flattened(scene) (scene/mesh_placement.h),
    // the scene triangle itself where the scene has no instances.
    std::vector<uint32_t> placed;
    double seconds = 0.0; // wall time of the tracing threads
};

struct EmbreeOcclusion {
    std::vector<uint8_t> occluded;
    double seconds = 0.0;
};

// Fast: Embree's default, Möller–Trumbore's test on precomputed edges
// (Triangle4) in a tree with spatial splits (RTC_BUILD_QUALITY_HIGH). Robust:
// Embree's Plücker test on the corners (Triangle4v), watertight along shared
// edges, with conservative box tests in the meshes' trees (not in the tree of
// instances), in a tree without spatial splits: Embree 3 builds robust scenes
// with its plain binned SAH whatever the quality asked. Unlike ours, neither
// bounds the error of t. Robust queries ask for the open interval: the test
// reports a bounce ray's own surface at t = 0 and a segment's far surface at
// t = 1 (a third of the Cornell box's bounce rays, with tnear = 0), so they
// start at the least normal float and a segment ends at the float below 1.
enum class EmbreeMode { Fast, Robust };

class EmbreeScene {
public:
    // The scene's world-space triangles in one geometry (primID = triangle),
    // and each instance of a shared mesh an instance of that mesh's scene.
    EmbreeScene(const Scene& scene, unsigned threads, EmbreeMode mode = EmbreeMode::Fast);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // Closest hits, t in (0, t_far] (robust: from the least normal float).
    EmbreeHits intersect1(const std::vector<BatchRay>& rays, float t_far = INFINITY) const;
    // The same, eight consecutive rays per call.
    EmbreeHits intersect8(const std::vector<BatchRay>& rays) const;
    // Any hit along each ray's direction taken as the whole segment, t in (0, 1]
    // (robust: the open interval, as above).
    EmbreeOcclusion occluded1(const std::vector<BatchRay>& rays) const;

    // Wall time of the scene's build (rtcCommitScene) on the threads given.
    double build_seconds() const { return build_seconds_; }

private:
    // The scene triangle and the placed one that a hit names: geometry `geometry`
    // of the top scene (an instance's, or the world triangles'), triangle `prim` of it.
    void name_hit(uint32_t geometry, uint32_t prim, uint32_t* scene_triangle, uint32_t* placed) const;

    unsigned threads_;
    std::vector<uint32_t> first_; // by top-scene geometry: the scene triangle of its primID 0
    std::vector<uint32_t> placed_first_; // the same in flattened(scene)
    float t_near_ = 0.0f;       // where every query starts
    float segment_end_ = 1.0f;  // where a shadow segment ends (its direction is the whole segment)
    double build_seconds_ = 0.0;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
};

} // namespace wf::bench
