// test_instancing.cpp — a scene whose shared meshes are placed by instances
// renders as the same scene written out in world space: the two-level tree
// finds the same surfaces, and the surfaces mapped back to the world (point,
// error bound, normals, a mirror's front face) shade as the written-out
// triangles do. A GPU's kernels, whose traversal walks one tree, render the
// written-out scene; and the placements cost memory by the unique triangles.
#include <cmath>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "bvh/instance_bvh.h"
#include "gltf/gltf_loader.h"
#include "image/error_metrics.h"
#include "render/renderer.h"
#include "scene/environment_map.h"
#include "scene/mesh_placement.h"
#include "support/test_support.h"

namespace wf {
namespace {

RenderOutput render(const Scene& scene, RenderSettings settings) {
    settings.spp = 16;
    settings.seed = 9;
    return render_scene(test::cpu_device(), scene, *scene.camera, ImageSize{64, 48}, settings);
}

// The scene against its written-out self: the same paths up to the last bits
// of each hit, so the images agree far below the render's own noise, which a
// wrong map, normal or front face would not. `what` names it in the line the
// test reports.
void expect_renders_as_written_out(const Scene& scene, const std::string& what) {
    const RenderOutput placed = render(scene, RenderSettings{});
    const RenderOutput written_out = render(flattened(scene), RenderSettings{});
    ASSERT_TRUE(test::all_finite(placed.film.mean));
    const double noise = estimate_relmse(written_out.film.mean, written_out.film.variance_of_mean);
    const double difference = compare_images(placed.film.mean, written_out.film.mean).relmse;
    std::ostringstream line;
    line << what << " against its written-out self, 64x48, 16 spp: relMSE " << difference
         << ", the render's own noise " << noise;
    test::report_measured(line.str());
    EXPECT_LT(difference, 1e-5 * noise);
    EXPECT_GT(noise, 1e-4); // enough noise that the bound above means something
}

bool same_bytes(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

// Measured 1.8e-13 against a noise of 0.032; 3e-5 with the geometric normal mapped as a vector.
TEST(Instancing, RendersAsTheSceneWrittenOut) {
    expect_renders_as_written_out(test::instanced_cornell(), "instanced Cornell box");
}

// Normal maps: a placement's tangents are mapped with its surface, a mirror
// flipping their handedness (materials/surface_material.h), so a normal-mapped
// mesh placed twice, once mirrored and turned, shades as its written-out self.
TEST(Instancing, NormalMappedPlacementsRenderAsTheSceneWrittenOut) {
    Scene scene = load_gltf(WF_SOURCE_DIR "/../shared/scenes-real/NormalTangentTest/NormalTangentTest.gltf",
                            LoadOptions{-1, Instancing::Off});
    ASSERT_TRUE(scene.instances.empty());
    const Bounds box = scene.bounds();
    const glm::dvec3 centre(box.center()), extent(box.extent());
    scene.shared_meshes.push_back({0u, uint32_t(scene.triangle_count())});
    const glm::dmat4 to_origin = glm::translate(glm::dmat4(1.0), -centre);
    scene.instances.push_back({0u, glm::translate(glm::dmat4(1.0), glm::dvec3(-0.6 * extent.x, 0, 0)) * to_origin});
    scene.instances.push_back(
        {0u, glm::rotate(glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.6 * extent.x, 0, 0)),
                                    glm::dvec3(-1.0, 1.0, 1.0)),
                         0.4, glm::dvec3(0.0, 1.0, 0.0)) *
                 to_origin});
    scene.environment = std::make_shared<EnvironmentMap>(constant_environment(1.0f));
    scene.camera = test::camera_looking(glm::vec3(0.0f, 0.0f, 2.5f * float(extent.x)), {0, 0, -1}, {0, 1, 0}, 0.8f);
    // Measured 2.3e-11 against a noise of 1.7e-3; 6.7e-5 without the mirror's handedness.
    expect_renders_as_written_out(scene, "NormalTangentTest placed twice, once mirrored,");
}

// Every schedule and the megakernel: the same bytes (test_determinism.cpp's
// promise, on a two-level tree).
TEST(Instancing, EveryScheduleAndTheMegakernelGiveTheSameBytes) {
    const Scene scene = test::instanced_cornell();
    RenderSettings settings;
    settings.pool_size = 500;
    settings.schedule = Schedule::Refill;
    const Image reference = render(scene, settings).film.mean;
    settings.schedule = Schedule::Group;
    EXPECT_TRUE(same_bytes(reference, render(scene, settings).film.mean)) << "group";
    settings.trace_width = 2;
    EXPECT_TRUE(same_bytes(reference, render(scene, settings).film.mean)) << "group, two rays a work-item";
    settings.trace_width = RenderSettings{}.trace_width;
    settings.integrator = Integrator::Megakernel;
    EXPECT_TRUE(same_bytes(reference, render(scene, settings).film.mean)) << "megakernel";
}

// A GPU's traversal walks one tree: its render is the written-out scene's.
TEST(Instancing, GpuKernelsRenderTheSceneWrittenOut) {
    const Scene instanced = test::instanced_cornell();
    RenderSettings settings;
    settings.kernels = KernelKind::Gpu;
    const Image gpu = render(instanced, settings).film.mean;
    settings.kernels = KernelKind::Cpu;
    EXPECT_TRUE(same_bytes(gpu, render(flattened(instanced), settings).film.mean));
}

// The stiff case: a white Lambertian sphere placed far from the origin at
// scales from 0.01 to 100, mirrored and stretched, under a uniform sky of
// radiance 1. Every surface returns the sky, so every pixel is 1; a ray that
// slipped through a surface into a sphere (offsets too small for the maps'
// rounding) would be trapped and dim it.
TEST(Instancing, AWhiteFurnaceFarFromTheOriginReturnsTheSky) {
    Scene scene;
    const uint32_t white = test::add_material(scene, glm::vec3(1.0f), glm::vec3(0.0f), false);
    scene.shared_meshes.push_back({0u, 0u});
    test::add_smooth_sphere(scene, white, 16, 32);
    scene.shared_meshes[0].count = uint32_t(scene.triangle_count());
    const glm::dvec3 far(3.0e4, -2.0e4, 1.0e4);
    const auto place = [&](glm::dvec3 at, glm::dvec3 scale, double turn) {
        glm::dmat4 m = glm::translate(glm::dmat4(1.0), far + at);
        m = glm::rotate(m, turn, glm::normalize(glm::dvec3(1.0, 2.0, 3.0)));
        scene.instances.push_back({0u, glm::scale(m, scale)});
    };
    place({0, 0, 0}, glm::dvec3(100.0), 0.0);
    place({0, 0, 101.5}, glm::dvec3(1.0), 0.3);      // a hair above the big one
    place({30, 30, 95.2}, glm::dvec3(0.01), 1.0);    // tiny, above it, seen close up by the second camera
    place({-140, 0, 0}, {-30.0, 20.0, 30.0}, 2.0);   // mirrored and stretched
    place({0, 130, 0}, {50.0, 5.0, 50.0}, 0.7);      // a flattened disc
    place({130, 0, 0}, {30.0, 30.0, 0.3}, 0.4);      // a turned coin, stretched 100 times
    scene.environment = std::make_shared<EnvironmentMap>(constant_environment(1.0f));
    RenderSettings settings;
    settings.max_depth = WF_UNLIMITED_DEPTH;
    settings.spp = 16;
    settings.seed = 4;
    const ImageSize size{48, 48};
    for (const SceneCamera& camera :
         {test::camera_looking(glm::vec3(far + glm::dvec3(0, 0, 400)), {0, 0, -1}, {0, 1, 0}, 0.9f),
          test::camera_looking(glm::vec3(far + glm::dvec3(30, 30, 96.5)), {0, 0, -1}, {0, 1, 0}, 0.02f)}) {
        const FilmReadout film = render_scene(test::cpu_device(), scene, camera, size, settings).film;
        double sum = 0.0, variance = 0.0;
        const size_t n = size_t{size.width} * size.height;
        for (size_t i = 0; i < n; ++i) {
            sum += (film.mean.rgb[3 * i] + film.mean.rgb[3 * i + 1] + film.mean.rgb[3 * i + 2]) / 3.0;
            variance += film.variance_of_mean.rgb[3 * i];
        }
        const double mean = sum / n, standard_error = std::sqrt(variance) / n;
        std::ostringstream line;
        line << "instanced white furnace 3e4 from the origin, scales 0.01-100: mean " << mean << " +- "
             << standard_error;
        test::report_measured(line.str());
        EXPECT_NEAR(mean, 1.0, 0.005 + 3.0 * standard_error);
    }
}

TEST(Instancing, MemoryGrowsWithTheUniqueTriangles) {
    Scene scene = test::instanced_cornell();
    const MeshInstance placement = scene.instances.back();
    for (int i = 0; i < 200; ++i) scene.instances.push_back(placement);
    const size_t placed = make_device_scene_data(scene, build_scene_bvh(scene)).bytes();
    const size_t written_out = make_device_scene_data(flattened(scene), build_scene_bvh(flattened(scene))).bytes();
    test::report_measured("204 placements of a 10-triangle block: " + std::to_string(placed) + " bytes placed, " +
                          std::to_string(written_out) + " written out");
    EXPECT_LT(placed, written_out / 2);
}

} // namespace
} // namespace wf
