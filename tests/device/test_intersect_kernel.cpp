// test_intersect_kernel.cpp — the `intersect` stage kernel, run on the device
// over a queue of random rays, finds the same closest hits as the host's
// traversal (the same shared code, compiled by the device's compiler); and
// rays from one point, which it traces as packets (geometry/bvh_packet.h),
// the very bits it finds for them one by one.
#include <cmath>
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

// 10 000 small random triangles in [-1, 1]^3, every other one emissive.
DeviceSceneData random_soup(std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    Scene scene;
    const uint32_t plain = test::add_material(scene, glm::vec3(0.5f), glm::vec3(0.0f), false);
    const uint32_t emitter = test::add_material(scene, glm::vec3(0.5f), glm::vec3(1.0f), false);
    for (int t = 0; t < 10000; ++t) {
        const glm::vec3 c(unit(rng), unit(rng), unit(rng));
        const glm::vec3 a = c + 0.05f * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 b = c + 0.05f * glm::vec3(unit(rng), unit(rng), unit(rng));
        test::add_quad(scene, c, a, b, b, t % 2 ? emitter : plain); // the second triangle of each quad is degenerate
    }
    return make_device_scene_data(scene, build_bvh(scene.positions));
}

TEST(IntersectKernel, AgreesWithHostTraversal) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const DeviceSceneData data = random_soup(rng);
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

// Eight rays a point, in cones from a pixel's width to a hemisphere's (so
// some eights span several octants and go one by one); the same rays again
// with no two neighbours sharing a point, which the kernel traces one by one.
TEST(IntersectKernel, PacketsFindEachRaysOwnHit) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const DeviceSceneData data = random_soup(rng);
    const uint32_t points = 12000, per_point = 8;
    std::vector<test::TestRay> packed;
    for (uint32_t p = 0; p < points; ++p) {
        const glm::vec3 origin = 1.5f * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 axis = glm::normalize(-origin + 0.5f * glm::vec3(unit(rng), unit(rng), unit(rng)));
        const float spread = std::pow(10.0f, -3.0f + 3.0f * (0.5f + 0.5f * unit(rng))); // 1e-3 .. 1
        for (uint32_t i = 0; i < per_point; ++i)
            packed.push_back({origin, glm::normalize(axis + spread * glm::vec3(unit(rng), unit(rng), unit(rng)))});
    }
    std::vector<test::TestRay> alone(packed.size());
    for (uint32_t i = 0; i < packed.size(); ++i) alone[i % points * per_point + i / points] = packed[i];
    const std::vector<cl_float4> packed_hits = test::intersect_on_device(data, packed);
    const std::vector<cl_float4> alone_hits = test::intersect_on_device(data, alone);
    int hit_count = 0;
    for (uint32_t i = 0; i < packed.size(); ++i) {
        const cl_float4& a = alone_hits[i % points * per_point + i / points];
        ASSERT_EQ(std::memcmp(&packed_hits[i], &a, sizeof a), 0)
            << "ray " << i << ": t " << packed_hits[i].s[0] << " against " << a.s[0];
        int32_t triangle;
        std::memcpy(&triangle, &a.s[3], 4);
        hit_count += triangle >= 0;
    }
    EXPECT_GT(hit_count, static_cast<int>(packed.size() / 4)); // hits, not only misses
}

} // namespace
} // namespace wf
