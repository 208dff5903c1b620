// test_specialize.cpp — kernels compiled for a scene's features
// (host/device/scene_features.h) render exactly what the generic kernels render:
// the code left out only ever returned neutral values for such a scene (or, for
// an interface that reflects nothing over a black base, values a zero BSDF makes
// unused), and random numbers do not depend on the features. Bit for bit, on scenes that
// between them switch every feature on and off. And a GPU's kernels, run on
// the CPU device, render the CPU's kernels' bits.
#include <cstdlib>
#include <cstring>
#include <tuple>
#include <utility>
#include <vector>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "scene/environment_map.h"
#include "gltf/gltf_loader.h"
#include "render/renderer.h"
#include "device/scene_features.h"
#include "support/closed_meshes.h"
#include "support/test_support.h"

namespace wf {
namespace {

bool same_bits(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

void expect_specialized_equals_generic(const Scene& scene, const SceneCamera& camera, const std::string& what,
                                      Integrator integrator = Integrator::Wavefront) {
    RenderSettings settings;
    settings.spp = 4;
    settings.seed = 3;
    settings.integrator = integrator;
    const RenderOutput specialized = render_scene(test::cpu_device(), scene, camera, ImageSize{24, 24}, settings);
    settings.specialize = false;
    const RenderOutput generic = render_scene(test::cpu_device(), scene, camera, ImageSize{24, 24}, settings);
    test::report_measured(what + ": compiled for " + specialized.summary.features);
    EXPECT_TRUE(same_bits(specialized.film.mean, generic.film.mean)) << what;
    EXPECT_TRUE(same_bits(specialized.film.variance_of_mean, generic.film.variance_of_mean)) << what;
    EXPECT_EQ(specialized.summary.stats.shadow_rays, generic.summary.stats.shadow_rays) << what;
}

// The scene with KHR_materials_specular's factor 0 on every material: with no
// metal or transmission, nothing reflects at an interface (WF_HAS_SPECULAR 0).
Scene lambertian(Scene scene) {
    for (SceneMaterial& m : scene.materials) m.specular = 0.0f;
    return scene;
}

// A delta light, which no BSDF sample finds.
Scene floor_under_a_point_light() {
    Scene floor;
    test::add_quad(floor, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2},
                   test::add_material(floor, glm::vec3(0.5f), glm::vec3(0.0f), false));
    PunctualLight light{};
    light.type = WF_PUNCTUAL_POINT;
    light.position[1] = 1.0f;
    for (float& i : light.intensity) i = 2.0f;
    floor.punctual_lights.push_back(light);
    return floor;
}

SceneCamera floor_camera() { return test::camera_looking({0, 1, 2}, {0, -0.5f, -1}, {0, 1, 0}, 0.8f); }

TEST(Specialize, FeaturesAreWhatTheSceneUses) {
    const Scene cornell = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    EXPECT_EQ(describe_features(scene_features(cornell)), "layered BSDF, emissive triangles, specular");
    EXPECT_EQ(feature_defines(scene_features(cornell)),
              "-DWF_HAS_BSDF_LAYERED=1 -DWF_HAS_TEXTURES=0 -DWF_HAS_NORMAL_MAPS=0 -DWF_HAS_ALPHA_MASK=0 -DWF_HAS_VERTEX_COLORS=0 "
              "-DWF_HAS_EMISSIVE_TRIANGLES=1 "
              "-DWF_HAS_PUNCTUAL_LIGHTS=0 -DWF_HAS_ENVIRONMENT=0 -DWF_HAS_SPECULAR=1 -DWF_HAS_TRANSMISSION=0 "
              "-DWF_HAS_CLEARCOAT=0 -DWF_HAS_SHEEN=0 "
              "-DWF_HAS_INSTANCES=0");
    const Scene helmet = load_gltf(WF_SOURCE_DIR "/../shared/scenes-real/DamagedHelmet/DamagedHelmet.glb");
    EXPECT_EQ(describe_features(scene_features(helmet)),
              "layered BSDF, textures, normal maps, emissive triangles, specular");
    EXPECT_EQ(describe_features(SceneFeatures::all()),
              "layered BSDF, textures, normal maps, alpha mask, vertex colours, emissive triangles, punctual lights, "
              "environment, specular, transmission, clear coat, sheen");
    const Scene car = load_gltf(WF_SOURCE_DIR "/../shared/scenes-real/ToyCar/ToyCar.gltf");
    EXPECT_EQ(describe_features(scene_features(car)),
              "layered BSDF, textures, normal maps, emissive triangles, specular, transmission, clear coat, sheen");
    EXPECT_EQ(describe_features(scene_features(lambertian(cornell))), "layered BSDF, emissive triangles");
}

TEST(Specialize, SpecializedKernelsRenderTheGenericBits) {
    const Scene cornell = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    expect_specialized_equals_generic(cornell, *cornell.camera, "Cornell box");
    // No interface reflects: the kind's base alone, its albedo tables unread.
    // One wall black, whose base chooses the interface that reflects nothing.
    // Both integrators: the group schedule's lanes, and width 1.
    Scene black_wall = lambertian(cornell);
    black_wall.materials[1].base_color = glm::vec3(0.0f);
    for (const Integrator integrator : {Integrator::Wavefront, Integrator::Megakernel}) {
        const std::string name = std::string(", ") + integrator_name(integrator);
        expect_specialized_equals_generic(black_wall, *cornell.camera, "Lambertian Cornell box, a black wall" + name,
                                          integrator);
        Scene smooth = black_wall;
        smooth.materials[1].roughness = 0.0f; // a Dirac interface over no albedo
        expect_specialized_equals_generic(smooth, *cornell.camera, "a smooth black wall" + name, integrator);
        Scene coated = black_wall; // a black base under a smooth coat: p_coat 1 (lobes/coat.inc)
        coated.materials[1].clearcoat = 1.0f;
        expect_specialized_equals_generic(coated, *cornell.camera, "a black wall under a clear coat" + name,
                                          integrator);
    }

    Scene helmet = load_gltf(WF_SOURCE_DIR "/../shared/scenes-real/DamagedHelmet/DamagedHelmet.glb");
    helmet.environment = std::make_shared<EnvironmentMap>(constant_environment(1.0f));
    expect_specialized_equals_generic(
        helmet, test::camera_looking({0, 0, 3}, {0, 0, -1}, {0, 1, 0}, 0.8f), "DamagedHelmet under a sky");

    const Scene vase = load_gltf(WF_SOURCE_DIR "/../shared/scenes-real/TransmissionTest/TransmissionTest.gltf");
    Scene lit_vase = vase;
    light_unlit_scene(lit_vase);
    expect_specialized_equals_generic(lit_vase, *vase.camera, "TransmissionTest (alpha mask)");

    Scene car = load_gltf(WF_SOURCE_DIR "/../shared/scenes-real/ToyCar/ToyCar.gltf");
    car.environment = std::make_shared<EnvironmentMap>(constant_environment(1.0f));
    expect_specialized_equals_generic(car, *car.camera, "ToyCar under a sky (clear coat, sheen)");

    expect_specialized_equals_generic(floor_under_a_point_light(), floor_camera(), "floor under a point light");
}

// --kernels gpu builds what a GPU gets (render_program_source): static
// functions, lanes of one path, the glass table read from the scene, not
// from the constant bank, and on a GPU's default schedule (refill) shade in
// two kernels (stages/shade_two_kernels.h). The same floats in the same order:
// the same bits.
void expect_gpu_kernels_equal_cpu_kernels(const Scene& scene, const SceneCamera& camera, const std::string& what,
                                          Integrator integrator, uint32_t lane_width = 0,
                                          Schedule schedule = Schedule::Auto) {
    RenderSettings settings;
    settings.spp = 4;
    settings.seed = 5;
    settings.integrator = integrator;
    settings.schedule = schedule;
    if (lane_width != 0) { // a GPU's program with the group schedule's lanes, which read the glass table too
        settings.schedule = Schedule::Group;
        settings.lane_width = lane_width;
    }
    settings.kernels = KernelKind::Cpu;
    const RenderOutput cpu = render_scene(test::cpu_device(), scene, camera, ImageSize{24, 24}, settings);
    settings.kernels = KernelKind::Gpu;
    const RenderOutput gpu = render_scene(test::cpu_device(), scene, camera, ImageSize{24, 24}, settings);
    EXPECT_TRUE(same_bits(cpu.film.mean, gpu.film.mean))
        << what << ", " << integrator_name(integrator) << ", " << schedule_name(settings.schedule);
    EXPECT_TRUE(same_bits(cpu.film.variance_of_mean, gpu.film.variance_of_mean)) << what;
    EXPECT_EQ(cpu.summary.stats.shadow_rays, gpu.summary.stats.shadow_rays) << what;
}

TEST(Specialize, GpuKernelsRenderTheCpuKernelsBits) {
    Scene glass; // a rough solid glass ball under a sky: its BSDF reads the glass table
    const uint32_t m = test::add_material(glass, glm::vec3(1.0f), glm::vec3(0.0f), false);
    glass.materials[m].metallic = 0.0f;
    glass.materials[m].roughness = 0.4f;
    glass.materials[m].transmission = 1.0f;
    const test::Mesh ball = test::icosphere(2, 1.0f, glm::vec3(0.0f));
    for (const auto& f : ball.faces) { // front faces outward
        glm::vec3 a = ball.vertices[f[0]], b = ball.vertices[f[1]], c = ball.vertices[f[2]];
        if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0.0f) std::swap(b, c);
        test::add_triangle(glass, a, b, c, m);
    }
    glass.environment = std::make_shared<EnvironmentMap>(constant_environment(1.0f));
    const Scene cornell = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    const SceneCamera glass_camera = test::camera_looking({0, 0, 3.5f}, {0, 0, -1}, {0, 1, 0}, 0.7f);
    const Scene lambertian_cornell = lambertian(cornell);
    for (const Integrator integrator : {Integrator::Wavefront, Integrator::Megakernel}) {
        expect_gpu_kernels_equal_cpu_kernels(glass, glass_camera, "rough glass ball", integrator);
        expect_gpu_kernels_equal_cpu_kernels(cornell, *cornell.camera, "Cornell box", integrator);
        expect_gpu_kernels_equal_cpu_kernels(lambertian_cornell, *cornell.camera, "Lambertian Cornell box",
                                             integrator);
    }
    // Shade in two kernels, as a GPU's default schedule runs it (include/wavefront/shade_record.h): under a
    // sky, an area light, a point light; through glass, off a mirror, and every lobe and texture of ToyCar's.
    Scene car = load_gltf(WF_SOURCE_DIR "/../shared/scenes-real/ToyCar/ToyCar.gltf");
    car.environment = std::make_shared<EnvironmentMap>(constant_environment(1.0f));
    const Scene mirror = load_gltf(WF_SOURCE_DIR "/scenes/cornell-mirror.gltf");
    const std::vector<std::tuple<const Scene*, SceneCamera, const char*>> refilled = {
        {&glass, glass_camera, "rough glass ball"},
        {&cornell, *cornell.camera, "Cornell box"},
        {&mirror, *mirror.camera, "Cornell box with a mirror"},
        {&car, *car.camera, "ToyCar under a sky"}};
    for (const auto& [scene, camera, what] : refilled)
        expect_gpu_kernels_equal_cpu_kernels(*scene, camera, what, Integrator::Wavefront, 0, Schedule::Refill);
    expect_gpu_kernels_equal_cpu_kernels(floor_under_a_point_light(), floor_camera(), "floor under a point light",
                                         Integrator::Wavefront, 0, Schedule::Refill);
    expect_gpu_kernels_equal_cpu_kernels(glass, glass_camera, "rough glass ball, 8 lanes", Integrator::Wavefront, 8);
}

// The GPU's short stack, shrunk to one group (WF_KERNEL_OPTIONS is appended to
// the build options), drops groups on every second push and finds them again
// from the top of the tree (rebuild_stack, geometry/bvh_traverse.h): the
// same bits. DamagedHelmet's tree is deep enough to drop many at a time.
TEST(Specialize, GpuKernelsRebuildingTheirStackRenderTheCpuKernelsBits) {
    Scene helmet = load_gltf(WF_SOURCE_DIR "/../shared/scenes-real/DamagedHelmet/DamagedHelmet.glb");
    helmet.environment = std::make_shared<EnvironmentMap>(constant_environment(1.0f));
    const Scene cornell = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    const char* before = std::getenv("WF_KERNEL_OPTIONS");
    const std::string kept = before ? before : "";
    setenv("WF_KERNEL_OPTIONS", (kept + " -DWF_GPU_STACK_SIZE=1").c_str(), 1);
    for (const Integrator integrator : {Integrator::Wavefront, Integrator::Megakernel}) {
        expect_gpu_kernels_equal_cpu_kernels(
            helmet, test::camera_looking({0, 0, 3}, {0, 0, -1}, {0, 1, 0}, 0.8f), "DamagedHelmet", integrator);
        expect_gpu_kernels_equal_cpu_kernels(cornell, *cornell.camera, "Cornell box", integrator);
    }
    if (before)
        setenv("WF_KERNEL_OPTIONS", kept.c_str(), 1);
    else
        unsetenv("WF_KERNEL_OPTIONS");
}

} // namespace
} // namespace wf
