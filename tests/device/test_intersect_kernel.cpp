// test_intersect_kernel.cpp — the `intersect` stage kernel, run on the device
// over a queue of random rays, finds the same closest hits as the host's
// traversal (the same shared code, compiled by the device's compiler).
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "bvh/bvh_builder.h"
#include "device/device_scene.h"
#include "geometry/bvh_traverse.h"
#include "support/test_support.h"

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
    const uint32_t rays = 100000;
    std::vector<test::TestRay> queue(rays);
    for (test::TestRay& r : queue) {
        r.origin = 1.5f * glm::vec3(unit(rng), unit(rng), unit(rng));
        r.direction = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)));
    }
    const std::vector<cl_float4> hits = test::intersect_on_device(data, queue);

    int hit_count = 0;
    for (uint32_t i = 0; i < rays; ++i) {
        const wf_device::RayHit host = wf_device::bvh_closest_hit(data.nodes.data(), data.triangles.data(),
                                                                  queue[i].origin, queue[i].direction,
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
