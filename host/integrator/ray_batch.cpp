// ray_batch.cpp — each ray is a path slot of a pool sized to the batch, and
// each launch is set up the way the wavefront scheduler sets up the same stage,
// with render constants that switch off everything but the traversal.
#include "integrator/ray_batch.h"

#include <array>
#include <numeric>

namespace wf {
namespace {

std::vector<cl_float4> to_float4(const std::vector<BatchRay>& rays, glm::vec3 BatchRay::*member) {
    std::vector<cl_float4> v(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        const glm::vec3& p = rays[i].*member;
        v[i] = {{p.x, p.y, p.z, 0.0f}};
    }
    return v;
}

RenderParams batch_params(uint32_t count) {
    RenderParams params{};
    params.pool_size = count;
    params.pixel_count = count;
    params.traced_pixels = count;
    return params;
}

} // namespace

RayBatch::RayBatch(const OpenClDevice& device, const cl::Program& program, const DeviceScene& scene,
                   const std::vector<BatchRay>& rays)
    : device_(device), scene_(scene), pool_(device.context, static_cast<uint32_t>(rays.size())),
      params_(batch_params(pool_.size())), film_(device.context, device.queue, 1, 1, 0),
      intersect_(program, "intersect"), shadow_(program, "intersect_shadow") {
    pool_.clear(device.queue); // no slot holds anything a kernel could trip on
    const size_t bytes = rays.size() * sizeof(cl_float4);
    const std::vector<cl_float4> origins = to_float4(rays, &BatchRay::origin);
    const std::vector<cl_float4> directions = to_float4(rays, &BatchRay::direction);
    device.queue.enqueueWriteBuffer(pool_.field(PathField::ray_origin), CL_TRUE, 0, bytes, origins.data());
    device.queue.enqueueWriteBuffer(pool_.field(PathField::ray_direction), CL_TRUE, 0, bytes, directions.data());
}

RayBatch::RayBatch(const OpenClDevice& device, const cl::Program& program, const DeviceScene& scene,
                   const Camera& camera, uint32_t seed)
    : device_(device), scene_(scene), pool_(device.context, camera.width * camera.height),
      params_(batch_params(pool_.size())), camera_(camera), film_(device.context, device.queue, 1, 1, 0),
      intersect_(program, "intersect"), shadow_(program, "intersect_shadow") {
    // A pool as large as the image: slot i starts sample 0 of pixel i.
    RenderParams params = params_;
    params.spp = 1;
    params.seed = seed;
    pool_.clear(device.queue);
    queue_all(WF_QUEUE_REGENERATE);
    cl::Kernel generate(program, "generate");
    set_stage_args(generate, StageArgs{pool_, params, camera_, scene_, film_});
    launch(generate);
}

std::vector<BatchRay> RayBatch::rays() const {
    const size_t bytes = size_t{size()} * sizeof(cl_float4);
    std::vector<cl_float4> origins(size()), directions(size());
    device_.queue.enqueueReadBuffer(pool_.field(PathField::ray_origin), CL_FALSE, 0, bytes, origins.data());
    device_.queue.enqueueReadBuffer(pool_.field(PathField::ray_direction), CL_TRUE, 0, bytes, directions.data());
    std::vector<BatchRay> rays(size());
    for (size_t i = 0; i < rays.size(); ++i) {
        rays[i].origin = {origins[i].s[0], origins[i].s[1], origins[i].s[2]};
        rays[i].direction = {directions[i].s[0], directions[i].s[1], directions[i].s[2]};
    }
    return rays;
}

void RayBatch::queue_all(uint32_t queue) const {
    std::vector<cl_uint> slots(size());
    std::iota(slots.begin(), slots.end(), 0u);
    std::array<cl_uint, WF_COUNTER_COUNT> counters{};
    counters[queue] = size();
    device_.queue.enqueueWriteBuffer(pool_.queues, CL_TRUE, sizeof(cl_uint) * queue * size_t{size()},
                                     sizeof(cl_uint) * size(), slots.data());
    device_.queue.enqueueWriteBuffer(pool_.counters, CL_TRUE, 0, sizeof(counters), counters.data());
}

double RayBatch::launch(cl::Kernel& kernel) const {
    // Rounded up to whole work-groups; the kernel stops at the queue length.
    const size_t local = RenderSettings{}.local_size;
    const size_t global = (size_t{size()} + local - 1) / local * local;
    cl::Event event;
    device_.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(local), nullptr,
                                       &event);
    event.wait();
    const auto start = event.getProfilingInfo<CL_PROFILING_COMMAND_START>();
    const auto end = event.getProfilingInfo<CL_PROFILING_COMMAND_END>();
    return static_cast<double>(end - start) * 1e-9;
}

ClosestHits RayBatch::closest_hits() const {
    queue_all(WF_QUEUE_EXTEND);
    set_stage_args(intersect_, StageArgs{pool_, params_, camera_, scene_, film_});
    ClosestHits result;
    result.kernel_seconds = launch(intersect_);
    result.hits.resize(size());
    device_.queue.enqueueReadBuffer(pool_.field(PathField::hit), CL_TRUE, 0, size_t{size()} * sizeof(cl_float4),
                                    result.hits.data());
    return result;
}

AnyHits RayBatch::any_hits() const {
    // A segment left unoccluded adds its shadow radiance, (1, 1, 1), to a
    // radiance of 0: what is read back says which were blocked.
    const size_t bytes = size_t{size()} * sizeof(cl_float4);
    const cl::CommandQueue& q = device_.queue;
    q.enqueueCopyBuffer(pool_.field(PathField::ray_origin), pool_.field(PathField::shadow_origin), 0, 0, bytes);
    q.enqueueCopyBuffer(pool_.field(PathField::ray_direction), pool_.field(PathField::shadow_segment), 0, 0, bytes);
    q.enqueueFillBuffer(pool_.field(PathField::shadow_radiance), cl_float4{{1.0f, 1.0f, 1.0f, 0.0f}}, 0, bytes);
    q.enqueueFillBuffer(pool_.field(PathField::radiance), cl_float4{{0.0f, 0.0f, 0.0f, 0.0f}}, 0, bytes);
    queue_all(WF_QUEUE_SHADOW);
    set_stage_args(shadow_, StageArgs{pool_, params_, camera_, scene_, film_});
    AnyHits result;
    result.kernel_seconds = launch(shadow_);
    std::vector<cl_float4> radiance(size());
    q.enqueueReadBuffer(pool_.field(PathField::radiance), CL_TRUE, 0, bytes, radiance.data());
    result.occluded.resize(size());
    for (size_t i = 0; i < radiance.size(); ++i) result.occluded[i] = radiance[i].s[0] == 0.0f;
    return result;
}

} // namespace wf
