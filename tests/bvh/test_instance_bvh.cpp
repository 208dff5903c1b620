// test_instance_bvh.cpp — the two-level tree of a scene with shared meshes
// (host/bvh/instance_bvh.h) keeps the traversal's promise: a query answers
// what testing every triangle of every placement, with the ray mapped into
// the placement's space as the traversal maps it, and passing each hit to the
// selection rule would answer, to the bit; and the two-level tree holds each
// shared mesh's triangles once, however many times it is placed.
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "bvh/instance_bvh.h"
#include "device/device_scene.h"
#include "geometry/bvh_traverse.h"
#include "support/test_support.h"
#include "scene/mesh_placement.h"

#include <glm/gtc/matrix_transform.hpp>

namespace wf {
namespace {

using wf_device::RayHit;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

uint32_t bits(float f) {
    uint32_t b;
    std::memcpy(&b, &f, 4);
    return b;
}

bool same_hit(const RayHit& a, const RayHit& b) {
    return a.triangle == b.triangle && a.instance == b.instance && bits(a.t) == bits(b.t) &&
           bits(a.u) == bits(b.u) && bits(a.v) == bits(b.v);
}

// The BVH positions of the tree under node `child`, collected leaf by leaf.
void positions_under(const std::vector<BvhNode>& nodes, uint32_t child, std::vector<uint32_t>& out) {
    if (child & WF_BVH_LEAF) {
        const uint32_t first = child & WF_BVH_FIRST_MASK;
        const uint32_t count = ((child & ~WF_BVH_LEAF) >> WF_BVH_COUNT_SHIFT) + 1u;
        for (uint32_t i = first; i < first + count; ++i) out.push_back(i);
        return;
    }
    for (uint32_t c : nodes[child].child)
        if (c != 0u) positions_under(nodes, c, out);
}

struct PlacedScene {
    explicit PlacedScene(const Scene& s) : scene(s), bvh(build_scene_bvh(s)), data(make_device_scene_data(s, bvh)) {
        for (const Instance& placement : data.instances) {
            positions.emplace_back();
            positions_under(data.nodes, data.nodes[placement.root].child[0], positions.back());
        }
    }
    RayHit closest(glm::vec3 o, glm::vec3 d, float t_max) const {
        return wf_device::bvh_closest_hit(data.nodes.data(), data.triangles.data(), o, d, t_max,
                                          data.instances.data());
    }
    // Brute force: every triangle of every placement, the ray mapped into the
    // placement's space as the traversal maps it.
    RayHit brute_force(glm::vec3 o, glm::vec3 d, float t_max) const {
        wf_device::HitSelection selection = wf_device::no_hits(t_max);
        for (size_t i = 0; i < data.instances.size(); ++i) {
            const Instance& placement = data.instances[i];
            const wf_device::WatertightRay ray = wf_device::watertight_ray(
                wf_device::map_point(placement.world_to_object, o), wf_device::map_vector(placement.world_to_object, d));
            for (uint32_t position : positions[i]) {
                const uint32_t block = position / WF_BLOCK_LANES;
                const wf_device::TriangleLanes lanes = wf_device::block_lanes(&ray, &data.triangles[block]);
                wf_device::TriangleHit hits[WF_BLOCK_LANES];
                const uint32_t lane = position % WF_BLOCK_LANES;
                if (wf_device::intersect_triangles(&ray, &lanes, 1u << lane, t_max, selection.window_end, hits))
                    wf_device::select_hit(&selection, &hits[lane], int32_t(position), int32_t(i),
                                          data.triangles[block].light[lane] >= 0);
            }
        }
        return wf_device::selected_hit(&selection);
    }

    const Scene& scene;
    Bvh bvh;
    DeviceSceneData data;
    std::vector<std::vector<uint32_t>> positions; // by placement, its tree's BVH positions
};

// A crowd: a mesh of random triangles placed 60 times, turned, stretched and
// mirrored at random over [0, 550]^3, and a few world-space triangles, so that
// the top tree has levels of its own.
Scene crowd() {
    Scene scene;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), where(0.0f, 550.0f), size(5.0f, 40.0f);
    const uint32_t material = test::add_material(scene, glm::vec3(0.5f), glm::vec3(0.0f), false);
    for (int i = 0; i < 6; ++i) {
        const glm::vec3 a(where(rng), where(rng), where(rng));
        test::add_triangle(scene, a, a + 60.0f * glm::vec3(unit(rng), unit(rng), unit(rng)),
                           a + 60.0f * glm::vec3(unit(rng), unit(rng), unit(rng)), material);
    }
    scene.shared_meshes.push_back({uint32_t(scene.triangle_count()), 40u});
    for (int i = 0; i < 40; ++i) {
        const glm::vec3 a(unit(rng), unit(rng), unit(rng));
        test::add_triangle(scene, a, a + 0.5f * glm::vec3(unit(rng), unit(rng), unit(rng)),
                           a + 0.5f * glm::vec3(unit(rng), unit(rng), unit(rng)), material);
    }
    for (int i = 0; i < 60; ++i) {
        glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(where(rng), where(rng), where(rng)));
        m = glm::rotate(m, double(3.0f * unit(rng)), glm::dvec3(unit(rng), unit(rng), 1.0));
        m = glm::scale(m, glm::dvec3(size(rng), size(rng), size(rng)) * (i % 3 == 0 ? -1.0 : 1.0));
        scene.instances.push_back({0, m});
    }
    return scene;
}

// A scene built in code has no texture coordinates, tangents or colours:
// written out, it still has none, and its triangles are the placed ones.
TEST(InstanceBvh, ACrowdBuiltInCodeIsWrittenOut) {
    const Scene scene = crowd();
    const Scene flat = flattened(scene);
    EXPECT_EQ(flat.triangle_count(), scene.placed_triangle_count());
    EXPECT_TRUE(flat.uv0.empty() && flat.tangents.empty() && flat.colors.empty());
    EXPECT_TRUE(flat.instances.empty());
}

TEST(InstanceBvh, SharedMeshesAreStoredOnce) {
    const Scene scene = test::instanced_cornell();
    ASSERT_EQ(scene.instances.size(), 4u);
    const PlacedScene placed(scene);
    // The world's triangles and one block: 32 triangles in all, not 22 + 4 x 10.
    size_t stored = 0;
    for (uint32_t t : placed.bvh.order) stored += t != kNoTriangle ? 1u : 0u;
    EXPECT_EQ(stored, scene.triangle_count());
    EXPECT_EQ(scene.placed_triangle_count(), scene.world_triangle_count() + 4 * scene.shared_meshes[0].count);
    // Five placements: the world under the identity, and the four blocks, two of them mirrored or not.
    ASSERT_EQ(placed.data.instances.size(), 5u);
    int mirrored = 0;
    for (const Instance& p : placed.data.instances) mirrored += p.handedness < 0.0f ? 1 : 0;
    EXPECT_EQ(mirrored, 1);
    // The scene's box holds the flattened scene's (a turned mesh's box, mapped, is larger than its triangles').
    const Bounds flat = flattened(scene).bounds(), placed_box = scene.bounds();
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(placed_box.lo[axis], flat.lo[axis]) << axis;
        EXPECT_GE(placed_box.hi[axis], flat.hi[axis]) << axis;
    }
}

class InstanceTraversal : public ::testing::TestWithParam<int> {};

TEST_P(InstanceTraversal, AnswersWhatBruteForceOverEveryPlacementAnswers) {
    const Scene scene = GetParam() == 0 ? test::instanced_cornell() : crowd();
    const PlacedScene placed(scene);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> inside(10.0f, 540.0f);
    std::normal_distribution<float> normal;
    int failures = 0, hits_on_placed_blocks = 0, rays = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 o(inside(rng), inside(rng), inside(rng));
        // Half the rays aimed at a point of a placed block, so that they meet every placement often.
        glm::vec3 d = glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
        if (i % 2 == 0) {
            const Instance& p = placed.data.instances[size_t(i / 2) % placed.data.instances.size()];
            const glm::vec3 foot(p.object_to_world[0][3], p.object_to_world[1][3] + 20.0f, p.object_to_world[2][3]);
            d = foot - o;
        }
        for (const float t_max : {kInfinity, 0.5f}) {
            ++rays;
            const RayHit traversed = placed.closest(o, d, t_max);
            const RayHit brute = placed.brute_force(o, d, t_max);
            if (!same_hit(traversed, brute) && ++failures <= 5)
                ADD_FAILURE() << "ray " << i << ": traversal hit triangle " << traversed.triangle << " of placement "
                              << traversed.instance << " at " << traversed.t << ", brute force "
                              << brute.triangle << " of " << brute.instance << " at " << brute.t;
            const bool any = wf_device::bvh_any_hit(placed.data.nodes.data(), placed.data.triangles.data(), o, d,
                                                    t_max, placed.data.instances.data()) != 0;
            if (any != (brute.triangle >= 0) && ++failures <= 5) ADD_FAILURE() << "ray " << i << ": any hit";
            const Instance& p = placed.data.instances[size_t(std::max(brute.instance, 0))];
            hits_on_placed_blocks += brute.triangle >= 0 && p.object_to_world[0][0] != 1.0f ? 1 : 0;
        }
        // Two rays in turn: each the answer it gets alone.
        const glm::vec3 origin[2] = {o, glm::vec3(inside(rng), inside(rng), inside(rng))};
        const glm::vec3 direction[2] = {d, -d};
        RayHit pair[2];
        wf_device::bvh_traverse_pair(placed.data.nodes.data(), placed.data.triangles.data(), origin, direction,
                                     kInfinity, 0, placed.data.instances.data(), pair);
        for (int k = 0; k < 2; ++k)
            if (!same_hit(pair[k], placed.closest(origin[k], direction[k], kInfinity)) && ++failures <= 5)
                ADD_FAILURE() << "ray " << i << ": two rays in turn";
    }
    EXPECT_EQ(failures, 0) << "of " << rays << " rays";
    EXPECT_GT(hits_on_placed_blocks, rays / 10) << "the rays should meet the placed meshes often";
}

INSTANTIATE_TEST_SUITE_P(Scenes, InstanceTraversal, ::testing::Values(0, 1),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return std::string(info.param == 0 ? "instanced_cornell" : "crowd");
                         });

} // namespace
} // namespace wf
