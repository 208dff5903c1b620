// test_intersect_kernel.cpp — the `intersect` stage kernel, run on the device
// over a queue of random rays, finds the same closest hits as the host's
// traversal (the same shared code, compiled by the device's compiler).
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "bvh_builder.h"
#include "device_scene.h"
#include "geometry/bvh_traverse.h"
#include "kernel_program.h"
#include "path_pool.h"
#include "test_support.h"

namespace wf {
namespace {

TEST(IntersectKernel, AgreesWithHostTraversal) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    Scene scene;
    const uint32_t m = test::add_material(scene, glm::vec3(0.5f), glm::vec3(0.0f), false);
    for (int t = 0; t < 10000; ++t) {
        const glm::vec3 c(unit(rng), unit(rng), unit(rng));
        const glm::vec3 a = c + 0.05f * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 b = c + 0.05f * glm::vec3(unit(rng), unit(rng), unit(rng));
        test::add_quad(scene, c, a, b, b, m); // the second triangle of each quad is degenerate
    }
    const Bvh bvh = build_bvh(scene.positions);
    const DeviceSceneData data = make_device_scene_data(scene, bvh);
    const OpenClDevice& device = test::cpu_device();
    const DeviceScene uploaded = upload_scene(device.context, data);

    const uint32_t rays = 100000;
    std::vector<cl_float4> origins(rays), directions(rays);
    std::vector<cl_uint> queue(rays);
    for (uint32_t i = 0; i < rays; ++i) {
        const glm::vec3 o = 1.5f * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 d = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)));
        origins[i] = {{o.x, o.y, o.z, 0.0f}};
        directions[i] = {{d.x, d.y, d.z, 0.0f}};
        queue[i] = i;
    }
    PathPool pool(device.context, rays);
    RenderParams params{};
    params.pool_size = rays;
    std::vector<cl_uint> counters(WF_COUNTER_COUNT, 0u);
    counters[WF_QUEUE_EXTEND] = rays;
    const cl::CommandQueue& q = device.queue;
    q.enqueueWriteBuffer(pool.field(PathField::ray_origin), CL_FALSE, 0, rays * sizeof(cl_float4), origins.data());
    q.enqueueWriteBuffer(pool.field(PathField::ray_direction), CL_FALSE, 0, rays * sizeof(cl_float4), directions.data());
    q.enqueueWriteBuffer(pool.queues, CL_FALSE, 0, rays * sizeof(cl_uint), queue.data());
    q.enqueueWriteBuffer(pool.counters, CL_FALSE, 0, counters.size() * sizeof(cl_uint), counters.data());

    const KernelProgram program = build_kernel_program(device, "wavefront.cl");
    cl::Kernel intersect(program.program, "intersect");
    const cl_uint next = pool.set_stage_args(intersect, params);
    intersect.setArg(next, uploaded.nodes);
    intersect.setArg(next + 1, uploaded.triangles);
    // Rounded up to whole work-groups; the kernel stops at the queue length.
    q.enqueueNDRangeKernel(intersect, cl::NullRange, cl::NDRange((rays + 63) / 64 * 64), cl::NDRange(64));
    std::vector<cl_float4> hits(rays);
    q.enqueueReadBuffer(pool.field(PathField::hit), CL_TRUE, 0, rays * sizeof(cl_float4), hits.data());

    int hit_count = 0;
    for (uint32_t i = 0; i < rays; ++i) {
        const glm::vec3 o(origins[i].s[0], origins[i].s[1], origins[i].s[2]);
        const glm::vec3 d(directions[i].s[0], directions[i].s[1], directions[i].s[2]);
        const wf_device::RayHit host = wf_device::bvh_closest_hit(data.nodes.data(), data.triangles.data(), o, d,
                                                                  std::numeric_limits<float>::infinity());
        int32_t device_triangle;
        std::memcpy(&device_triangle, &hits[i].s[3], 4);
        ASSERT_EQ(device_triangle, host.triangle) << "ray " << i;
        if (host.triangle >= 0) {
            ++hit_count;
            // The device compiler may contract a*b+c into one rounding: allow a few ulps.
            ASSERT_NEAR(hits[i].s[0], host.t, 4e-6f * host.t) << "ray " << i;
        }
    }
    EXPECT_GT(hit_count, rays / 10); // about 19% hit: the comparison covers hits, not only misses
}

} // namespace
} // namespace wf
