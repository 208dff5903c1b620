// test_sort_by_material.cpp — the counting sort of --sort-materials, run on the
// device over a shuffled extension queue: its output is the same slots, in
// ascending material key, misses first; and a render that sorts gives the
// bytes of one that does not.
#include <algorithm>
#include <cstring>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "gltf/gltf_loader.h"
#include "device/kernel_program.h"
#include "integrator/stage_args.h"
#include "render/renderer.h"
#include "support/test_support.h"

namespace wf {
namespace {

TEST(SortByMaterial, GroupsTheExtensionQueueByMaterial) {
    const OpenClDevice& device = test::cpu_device();
    const cl::CommandQueue& q = device.queue;
    constexpr uint32_t kPaths = 5000, kTriangles = 700, kKeys = 256;
    std::mt19937 rng(3);
    std::vector<uint32_t> material(kTriangles);
    for (uint32_t& m : material) m = rng() % 300; // more materials than keys: they share
    std::vector<TriangleBlock> triangles(kTriangles / WF_BLOCK_LANES + 1);
    for (uint32_t t = 0; t < kTriangles; ++t) triangles[t / WF_BLOCK_LANES].material[t % WF_BLOCK_LANES] = material[t];
    std::vector<cl_float4> hits(kPaths);
    std::vector<int32_t> hit_triangle(kPaths);
    for (uint32_t i = 0; i < kPaths; ++i) {
        hit_triangle[i] = rng() % 8 == 0 ? -1 : static_cast<int32_t>(rng() % kTriangles);
        std::memcpy(&hits[i].s[3], &hit_triangle[i], 4);
    }
    std::vector<cl_uint> queue(kPaths);
    std::iota(queue.begin(), queue.end(), 0u);
    std::shuffle(queue.begin(), queue.end(), rng);

    PathPool pool(device.context, kPaths);
    DeviceSceneData data;
    data.triangles = triangles;
    const DeviceScene scene = upload_scene(device.context, data);
    const Film film(device.context, q, 1, 1, 0);
    const Camera camera{};
    cl::Buffer key_counts(device.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * kKeys);
    cl::Buffer sorted(device.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * kPaths);
    q.enqueueWriteBuffer(pool.field(PathField::hit), CL_TRUE, 0, sizeof(cl_float4) * kPaths, hits.data());
    q.enqueueWriteBuffer(pool.queues, CL_TRUE, 0, sizeof(cl_uint) * kPaths, queue.data());
    std::vector<cl_uint> counters(WF_COUNTER_COUNT, 0u);
    counters[WF_QUEUE_EXTEND] = kPaths;
    q.enqueueWriteBuffer(pool.counters, CL_TRUE, 0, sizeof(cl_uint) * counters.size(), counters.data());
    q.enqueueFillBuffer(key_counts, 0u, 0, sizeof(cl_uint) * kKeys);

    const KernelProgram program = build_kernel_program(device, "wavefront.cl");
    RenderParams params{};
    params.pool_size = kPaths;
    cl::Kernel count(program.program, "count_materials"), scan(program.program, "scan_materials"),
        scatter(program.program, "scatter_materials");
    const StageArgs shared{pool, params, camera, scene, film};
    set_kernel_args(count, set_stage_args(count, shared), key_counts);
    scan.setArg(0, key_counts);
    set_kernel_args(scatter, set_stage_args(scatter, shared), key_counts, sorted);
    const cl::NDRange global((kPaths + 63) / 64 * 64), local(64);
    q.enqueueNDRangeKernel(count, cl::NullRange, global, local);
    q.enqueueNDRangeKernel(scan, cl::NullRange, local, local);
    q.enqueueNDRangeKernel(scatter, cl::NullRange, global, local);
    std::vector<cl_uint> result(kPaths);
    q.enqueueReadBuffer(sorted, CL_TRUE, 0, sizeof(cl_uint) * kPaths, result.data());

    auto key = [&](cl_uint slot) {
        const int32_t t = hit_triangle[slot];
        return t < 0 ? 0u : (material[t] + 1u) % kKeys;
    };
    for (uint32_t i = 1; i < kPaths; ++i) ASSERT_LE(key(result[i - 1]), key(result[i])) << "at " << i;
    std::vector<cl_uint> slots = result;
    std::sort(slots.begin(), slots.end());
    for (uint32_t i = 0; i < kPaths; ++i) ASSERT_EQ(slots[i], i); // each slot once
}

TEST(SortByMaterial, SortingChangesNoBit) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-teapot.gltf");
    RenderSettings settings;
    settings.spp = 4;
    settings.pool_size = 500;
    const Image plain = render_scene(test::cpu_device(), scene, *scene.camera, ImageSize{40, 30}, settings).film.mean;
    for (const Schedule schedule : {Schedule::Refill, Schedule::Fullest}) {
        settings.sort_materials = true;
        settings.schedule = schedule;
        const RenderOutput sorted = render_scene(test::cpu_device(), scene, *scene.camera, ImageSize{40, 30}, settings);
        ASSERT_EQ(plain.rgb.size(), sorted.film.mean.rgb.size());
        EXPECT_EQ(std::memcmp(plain.rgb.data(), sorted.film.mean.rgb.data(), plain.rgb.size() * sizeof(float)), 0)
            << schedule_name(schedule);
        EXPECT_GT(sorted.summary.stats.stages[STAGE_SORT].launches, 0u);
    }
}

} // namespace
} // namespace wf
