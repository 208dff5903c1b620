// ray_batch.h — a batch of rays traced on a device by the renderer's own stage
// kernels, outside a render: `intersect` for closest hits and
// `intersect_shadow` for any hit along a segment, each launch timed by its
// OpenCL profiling event. The device tests check the kernels' answers through
// it, and bench/ray_throughput.cpp measures their speed, so both look at the
// code a render runs, not at a copy of it.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "device/device_scene.h"
#include "device/opencl_device.h"
#include "film/film.h"
#include "integrator/path_integrator.h"
#include "integrator/path_pool.h"

namespace wf {

// The direction need not be unit; for any_hits() it is the whole segment.
struct BatchRay {
    glm::vec3 origin;
    glm::vec3 direction;
};

struct ClosestHits {
    std::vector<cl_float4> hits; // per ray, as the kernel stores them: t, u, v, triangle index as bits (-1: miss)
    double kernel_seconds = 0.0;
};

struct AnyHits {
    std::vector<uint8_t> occluded; // per ray: 1 when something lies on its segment
    double kernel_seconds = 0.0;
};

class RayBatch {
public:
    // `program` is kernels/wavefront.cl built for `device`; `scene` stays
    // uploaded while the batch is in use.
    RayBatch(const OpenClDevice& device, const cl::Program& program, const DeviceScene& scene,
             const std::vector<BatchRay>& rays);

    // The camera rays of a render's first sample, one per pixel of `camera`
    // in pixel order, made by the `generate` stage kernel with `seed`.
    RayBatch(const OpenClDevice& device, const cl::Program& program, const DeviceScene& scene, const Camera& camera,
             uint32_t seed);

    uint32_t size() const { return pool_.size(); }
    std::vector<BatchRay> rays() const; // read back, for tracing the same rays elsewhere

    // One launch of `intersect` over every ray, with no t limit.
    ClosestHits closest_hits() const;
    // One launch of `intersect_shadow` over every ray's segment (t in (0, 1)).
    AnyHits any_hits() const;

private:
    // Queues every slot, in slot order, in `queue`.
    void queue_all(uint32_t queue) const;
    // Launches `kernel` over every slot; returns its time on the device.
    double launch(cl::Kernel& kernel) const;

    const OpenClDevice& device_;
    const DeviceScene& scene_;
    PathPool pool_;
    RenderParams params_{};
    Camera camera_{};
    Film film_; // a pixel with no bounce layers: the stages bind one, and these launches never write it
    mutable cl::Kernel intersect_, shadow_;
};

} // namespace wf
