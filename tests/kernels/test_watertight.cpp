// test_watertight.cpp — no ray leaks through a closed mesh, however exactly it
// is aimed at the cracks between triangles: at vertices and at points of edges
// computed in float (tests/support/closed_meshes.h). From inside, every ray meets the
// mesh where it was aimed; from outside, every ray aimed at the part of the
// surface that faces it meets the surface there, not the far side. The host
// traversal answers more than 2,000,000 such rays, and the device `intersect`
// kernel, compiled by the device's compiler, a sample of more than 200,000.
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bvh/bvh_builder.h"
#include "support/closed_meshes.h"
#include "device/device_scene.h"
#include "geometry/bvh_traverse.h"
#include "support/test_support.h"

namespace wf {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Each ray's direction reaches the point aimed at, at t = 1.
using AimedRay = test::TestRay;

// A convex closed mesh, a point inside it, and the origins to aim from.
struct WatertightCase {
    std::string name;
    test::Mesh mesh;
    glm::vec3 inside;
    std::vector<glm::vec3> origins_inside, origins_outside;
};

// The mesh as a scene in BVH order, as the kernels read it.
DeviceSceneData scene_data(const test::Mesh& mesh) {
    Scene scene;
    const uint32_t material = test::add_material(scene, glm::vec3(0.5f), glm::vec3(0.0f), false);
    scene.mesh_names.push_back("closed mesh");
    scene.positions = mesh.corners();
    for (size_t t = 0; t < mesh.faces.size(); ++t) {
        const glm::vec3* p = &scene.positions[3 * t];
        const glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        scene.normals.insert(scene.normals.end(), {n, n, n});
        scene.triangle_material.push_back(material);
        scene.triangle_mesh.push_back(0);
    }
    return make_device_scene_data(scene, build_bvh(scene.positions));
}

// Rays from every inside origin to every crack point, and from every outside
// origin to the crack points whose faces all face it at more than 3 degrees
// from edge-on: nearer the silhouette, a point that float rounded off the
// surface may be passed by honestly.
std::vector<AimedRay> aimed_rays(const WatertightCase& c) {
    const std::vector<test::CrackPoint> points = test::crack_points(c.mesh);
    std::vector<AimedRay> rays;
    for (const glm::vec3& origin : c.origins_inside)
        for (const test::CrackPoint& p : points) rays.push_back(AimedRay{origin, p.point - origin});
    for (const glm::vec3& origin : c.origins_outside) {
        for (const test::CrackPoint& p : points) {
            bool facing = true;
            for (uint32_t f : p.faces) {
                const auto& face = c.mesh.faces[f];
                const glm::vec3 a = c.mesh.vertices[face[0]];
                glm::vec3 n = glm::normalize(glm::cross(c.mesh.vertices[face[1]] - a, c.mesh.vertices[face[2]] - a));
                if (glm::dot(n, a - c.inside) < 0.0f) n = -n; // outward
                facing = facing && glm::dot(n, glm::normalize(origin - a)) > 0.05f;
            }
            if (facing) rays.push_back(AimedRay{origin, p.point - origin});
        }
    }
    return rays;
}

// A convex mesh is met once along a ray from inside, and first where aimed
// along one from outside: at t = 1, up to the rounding of the point aimed at.
bool meets_where_aimed(float t, int32_t triangle) { return triangle >= 0 && t > 0.999f && t < 1.001f; }

std::vector<WatertightCase> cases() {
    const glm::vec3 c(1.0f, 2.0f, -0.5f); // an icosphere of radius 3 about c
    const glm::vec3 far(3.0e4f, -2.0e4f, 1.0e4f); // one of radius 50 about far
    return {
        {"icosphere", test::icosphere(6, 3.0f, c), c,
         {c, c + glm::vec3(0.7f, -1.1f, 0.3f), c + glm::vec3(0.0f, 0.0f, 2.9f), c + glm::vec3(-1.6f, 1.5f, 1.2f)},
         {c + glm::vec3(7.0f, 1.0f, -2.0f), c + glm::vec3(-0.5f, 9.0f, 3.0f), c + glm::vec3(0.0f, 0.0f, -3.2f),
          c + glm::vec3(40.0f, -30.0f, 20.0f)}},
        {"icosphere far from the origin", test::icosphere(6, 50.0f, far), far,
         {far, far + glm::vec3(10.0f, 20.0f, -30.0f)},
         {far + glm::vec3(200.0f, 50.0f, 100.0f), far - glm::vec3(0.0f, 0.0f, 60.0f)}},
        // The cube's centre lies on the planes of many boxes and triangles; its
        // rays to the face centres run along axes, to their middle lines in
        // axis planes. Origins outside in axis planes see edges of the cube.
        {"cube", test::subdivided_cube(64), glm::vec3(0.0f),
         {glm::vec3(0.0f), glm::vec3(0.3f, -0.6f, 0.85f)},
         {glm::vec3(3.0f, 0.0f, 0.0f), glm::vec3(2.5f, -3.0f, 4.0f), glm::vec3(0.0f, 1.5f, 1.5f)}}};
}

TEST(Watertight, RaysAtVerticesAndEdgesNeverLeak) {
    size_t host_rays = 0, device_rays = 0, host_leaks = 0, device_leaks_total = 0;
    for (const WatertightCase& c : cases()) {
        ASSERT_GE(c.mesh.faces.size(), 40000u) << c.name;
        const DeviceSceneData data = scene_data(c.mesh);
        const std::vector<AimedRay> rays = aimed_rays(c);
        size_t leaks = 0;
        for (const AimedRay& r : rays) {
            const wf_device::RayHit hit =
                wf_device::bvh_closest_hit(data.nodes.data(), data.triangles.data(), r.origin, r.direction, kInfinity);
            const bool any = wf_device::bvh_any_hit(data.nodes.data(), data.triangles.data(), r.origin, r.direction,
                                                    2.0f) != 0;
            if ((!meets_where_aimed(hit.t, hit.triangle) || !any) && ++leaks <= 5)
                ADD_FAILURE() << c.name << ": a leak from (" << r.origin.x << ", " << r.origin.y << ", "
                              << r.origin.z << ") at (" << r.origin.x + r.direction.x << ", "
                              << r.origin.y + r.direction.y << ", " << r.origin.z + r.direction.z << ")";
        }
        EXPECT_EQ(leaks, 0u) << c.name << ", host, of " << rays.size() << " rays";
        host_rays += rays.size();
        host_leaks += leaks;

        // The device: every eighth ray, all origins included.
        std::vector<AimedRay> sample;
        for (size_t i = 0; i < rays.size(); i += 8) sample.push_back(rays[i]);
        const std::vector<cl_float4> hits = test::intersect_on_device(data, sample);
        size_t device_leaks = 0;
        for (const cl_float4& h : hits) {
            int32_t triangle;
            std::memcpy(&triangle, &h.s[3], 4);
            device_leaks += !meets_where_aimed(h.s[0], triangle);
        }
        EXPECT_EQ(device_leaks, 0u) << c.name << ", device, of " << sample.size() << " rays";
        device_rays += sample.size();
        device_leaks_total += device_leaks;
    }
    test::report_measured("rays at shared edges and vertices: " + std::to_string(host_leaks) + " leaks of " +
                          std::to_string(host_rays) + " on the host, " + std::to_string(device_leaks_total) +
                          " of " + std::to_string(device_rays) + " on the device");
    EXPECT_GE(host_rays, 2'000'000u);
    EXPECT_GE(device_rays, 200'000u);
}

} // namespace
} // namespace wf
