// test_gltf_loader.cpp — wf::load_gltf as a whole: cameras, the real assets
// in shared/scenes-real (every one loads, with the inventory's triangle count,
// finite positions and unit normals), and scenes/cornell-box.gltf. Bad input,
// geometry and materials have their own files (test_gltf_*.cpp); the file
// builder they share is gltf_document.h.

#include "gltf/gltf_document.h"
#include "scene/mesh_placement.h"

#include <glm/gtc/constants.hpp>

#include <sstream>

namespace wf {
namespace {

// ---------------------------------------------------------------------------
// Cameras

class GltfCameraTest : public GltfLoaderTest {
protected:
    // Camera 0 orthographic, 1 perspective (placed under a moved parent),
    // 2 perspective but not placed in the scene.
    std::string write_cameras() {
        GltfDocument doc;
        doc.add_mesh_node("quad", triangle_primitive(doc.add_vec3(kQuad)));
        doc.gltf["cameras"] = {
            {{"type", "orthographic"},
             {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}},
            {{"name", "main"},
             {"type", "perspective"},
             {"perspective", {{"yfov", 0.5}, {"aspectRatio", 1.5}, {"znear", 0.1}}}},
            {{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
        doc.add_root({{"camera", 0}});
        // 90 degrees about y, scaled: looks along -x.
        const double half = std::sqrt(0.5);
        const int camera = doc.add_node({{"camera", 1},
                                         {"translation", {1, 2, 3}},
                                         {"rotation", {0, half, 0, half}},
                                         {"scale", {2, 2, 2}}});
        doc.add_root({{"translation", {0, 0, 10}}, {"children", {camera}}});
        return doc.write(dir_ / "cameras.gltf");
    }
};

TEST_F(GltfCameraTest, FirstPerspectiveCameraIsTakenByDefault) {
    const Scene scene = load_gltf(write_cameras());
    ASSERT_TRUE(scene.camera.has_value());
    expect_near(scene.camera->position, {1, 2, 13});
    expect_near(scene.camera->forward, {-1, 0, 0});
    expect_near(scene.camera->up, {0, 1, 0});
    EXPECT_FLOAT_EQ(scene.camera->vertical_fov, 0.5f);
    EXPECT_FLOAT_EQ(scene.camera->aspect, 1.5f);
}

TEST_F(GltfCameraTest, CameraIndexPicksOrRejects) {
    const std::string path = write_cameras();
    EXPECT_TRUE(load_gltf(path, LoadOptions{1}).camera.has_value());
    expect_mentions(load_error(path, LoadOptions{0}),
                    {"cameras.gltf", "camera 0", "not perspective"});
    expect_mentions(load_error(path, LoadOptions{2}), {"cameras.gltf", "camera 2", "not placed"});
    expect_mentions(load_error(path, LoadOptions{5}),
                    {"cameras.gltf", "camera 5", "does not exist"});
}

TEST_F(GltfCameraTest, NoCameraLeavesItEmpty) {
    GltfDocument doc;
    doc.add_mesh_node("quad", triangle_primitive(doc.add_vec3(kQuad)));
    EXPECT_FALSE(load_gltf(doc.write(dir_ / "no_camera.gltf")).camera.has_value());
}

// ---------------------------------------------------------------------------
// Real assets (shared/scenes-real, see its INVENTORY.md)

Scene load_real(const std::string& relative) { return load_gltf(kRealScenes + relative); }

TEST(GltfRealAssets, Triangle) {
    const Scene scene = load_real("Triangle/Triangle.gltf");
    expect_well_formed(scene);
    EXPECT_EQ(scene.triangle_count(), 1u);
    EXPECT_EQ(scene.materials.size(), 1u); // the default
    EXPECT_FALSE(scene.camera.has_value());
    expect_near(scene.normals[0], glm::normalize(geometric_normal(scene, 0)));
}

TEST(GltfRealAssets, BevyCornellBoxEmitsWithStrength100) {
    const Scene scene = load_real("CornellBox/CornellBox.glb");
    expect_well_formed(scene);
    EXPECT_EQ(scene.triangle_count(), 36u);
    const auto emitter =
        std::find_if(scene.materials.begin(), scene.materials.end(),
                     [](const SceneMaterial& m) { return m.emission != glm::vec3(0.0f); });
    ASSERT_NE(emitter, scene.materials.end());
    expect_near(emitter->emission, glm::vec3(100.0f), 1e-3f);
}

TEST(GltfRealAssets, MeshPrimitiveModes) {
    const Scene scene = load_real("MeshPrimitiveModes/MeshPrimitiveModes.gltf");
    expect_well_formed(scene);
    EXPECT_EQ(scene.triangle_count(), 16u);
    EXPECT_EQ(scene.warnings.size(), 4u); // points, lines, line loop, line strip
    for (const char* mesh :
         {"mesh with POINTS", "mesh with LINES", "mesh with LINE_LOOP", "mesh with LINE_STRIP"})
        EXPECT_NE(std::find_if(scene.warnings.begin(), scene.warnings.end(),
                               [&](const std::string& w) {
                                   return w.rfind(std::string("mesh '") + mesh + "': ", 0) == 0;
                               }),
                  scene.warnings.end())
            << mesh;
    // Strips and fans unroll with the list's winding: every triangle faces the same way.
    for (size_t t = 0; t < scene.triangle_count(); ++t)
        EXPECT_GT(glm::dot(geometric_normal(scene, t), geometric_normal(scene, 0)), 0.0f)
            << "triangle " << t;
}

TEST(GltfRealAssets, SimpleSparseAccessorIsApplied) {
    const Scene scene = load_real("SimpleSparseAccessor/SimpleSparseAccessor.gltf");
    expect_well_formed(scene);
    EXPECT_EQ(scene.triangle_count(), 12u);
    // The base positions lie in y <= 1; the sparse values lift vertices to y = 2, 3 and 4.
    EXPECT_FLOAT_EQ(scene.bounds().hi.y, 4.0f);
}

// Three of its meshes are placed twice, once mirrored: written out in world
// space where they are placed, or kept once and placed by instances, which
// flattened() writes out as the loader would.
TEST(GltfRealAssets, NegativeScaleKeepsFrontFacesOutward) {
    const std::string file = kRealScenes + "NegativeScaleTest/NegativeScaleTest.gltf";
    const Scene instanced = load_gltf(file, LoadOptions{-1, Instancing::All});
    EXPECT_TRUE(load_gltf(file).instances.empty()) << "3.9 K triangles: written out by default";
    expect_well_formed(instanced);
    EXPECT_EQ(instanced.shared_meshes.size(), 3u);
    EXPECT_EQ(instanced.instances.size(), 6u);
    EXPECT_EQ(instanced.placed_triangle_count(), 7724u);
    EXPECT_LT(instanced.triangle_count(), 7724u);
    const Scene written_out = load_gltf(file, LoadOptions{-1, Instancing::Off});
    EXPECT_TRUE(written_out.instances.empty());
    const Scene flat = flattened(instanced);
    for (const Scene* scene : {&written_out, &flat}) {
        expect_well_formed(*scene);
        EXPECT_EQ(scene->triangle_count(), 7724u);
        size_t disagreeing = 0;
        for (size_t t = 0; t < scene->triangle_count(); ++t)
            if (glm::dot(geometric_normal(*scene, t), scene->normals[3 * t]) < 0.0f) ++disagreeing;
        EXPECT_EQ(disagreeing, 0u);
    }
}

TEST(GltfRealAssets, CamerasFindsThePerspectiveCamera) {
    const Scene scene = load_real("Cameras/Cameras.gltf");
    expect_well_formed(scene);
    ASSERT_TRUE(scene.camera.has_value());
    expect_near(scene.camera->position, {0.5f, 0.5f, 3.0f});
    expect_near(scene.camera->forward, {0, 0, -1});
    EXPECT_FLOAT_EQ(scene.camera->vertical_fov, 0.7f);
    EXPECT_FLOAT_EQ(scene.camera->aspect, 1.0f);
}

TEST(GltfRealAssets, FoxIsNonIndexed) {
    const Scene scene = load_real("Fox/Fox.gltf");
    expect_well_formed(scene);
    EXPECT_EQ(scene.triangle_count(), 576u);
}

// One row of INVENTORY.md's summary table.
struct InventoryEntry {
    std::string file; // relative to scenes-real
    size_t triangles; // in the scene, instances counted
};

std::vector<InventoryEntry> read_inventory() {
    std::ifstream in(kRealScenes + "INVENTORY.md");
    std::vector<InventoryEntry> entries;
    std::string line;
    bool in_summary = false;
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) in_summary = line == "## Summary";
        if (!in_summary || line.rfind("| ", 0) != 0 || line.rfind("| asset", 0) == 0) continue;
        std::vector<std::string> cells;
        std::stringstream row(line.substr(1));
        for (std::string cell; std::getline(row, cell, '|');)
            cells.push_back(cell.substr(1, cell.size() - 2)); // drop the padding spaces
        std::string count = cells.at(3).substr(0, cells.at(3).find(" /"));
        count.erase(std::remove(count.begin(), count.end(), ','), count.end());
        entries.push_back({cells.at(0) + "/" + cells.at(1), std::stoul(count)});
    }
    return entries;
}

TEST(GltfRealAssets, EveryInventoryAssetLoads) {
    const std::vector<InventoryEntry> entries = read_inventory();
    ASSERT_EQ(entries.size(), 19u);
    for (const InventoryEntry& entry : entries) {
        SCOPED_TRACE(entry.file);
        Scene scene;
        ASSERT_NO_THROW(scene = load_real(entry.file));
        expect_well_formed(scene);
        EXPECT_EQ(scene.placed_triangle_count(), entry.triangles); // the inventory counts each placement
    }
}

// ---------------------------------------------------------------------------
// scenes/cornell-box.gltf (written by scenes/make_cornell_box.py)

TEST(GltfCornellBox, GeometryLightAndCamera) {
    const Scene scene = load_gltf(WF_SOURCE_DIR "/scenes/cornell-box.gltf");
    expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 32u); // 5 walls and the light of 2, two blocks of 5 faces x 2
    EXPECT_TRUE(scene.warnings.empty());

    const glm::vec3 le = 8.0f * glm::vec3(0.805f, 1.005f, 0.747f) +
                         15.6f * glm::vec3(1.027f, 0.900f, 0.740f) +
                         18.4f * glm::vec3(1.379f, 0.896f, 0.737f);
    const uint32_t light = mesh_index(scene, "light");
    const glm::vec3 box_centre(278.0f, 274.4f, 279.6f);
    const std::vector<std::string> walls = {"floor", "ceiling", "back_wall", "right_wall_green",
                                            "left_wall_red"};
    for (size_t t = 0; t < scene.triangle_count(); ++t) {
        const glm::vec3 normal = scene.normals[3 * t];
        // Flat normals: the shading normal is the front face's.
        expect_near(normal, glm::normalize(geometric_normal(scene, t)), 1e-4f);
        const std::string& mesh = scene.mesh_names[scene.triangle_mesh[t]];
        const SceneMaterial& material = scene.materials[scene.triangle_material[t]];
        if (scene.triangle_mesh[t] == light) {
            expect_near(normal, {0, -1, 0});
            EXPECT_FALSE(material.double_sided);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(material.emission[c], le[c], 1e-4f * le[c]);
        } else {
            EXPECT_EQ(material.emission, glm::vec3(0.0f)) << mesh;
        }
        if (std::find(walls.begin(), walls.end(), mesh) != walls.end()) {
            const glm::vec3* p = &scene.positions[3 * t];
            EXPECT_GT(glm::dot(normal, box_centre - (p[0] + p[1] + p[2]) / 3.0f), 0.0f)
                << mesh << " faces out";
        }
    }

    ASSERT_TRUE(scene.camera.has_value());
    expect_near(scene.camera->position, {278, 273, -800});
    expect_near(scene.camera->forward, {0, 0, 1});
    expect_near(scene.camera->up, {0, 1, 0});
    EXPECT_NEAR(scene.camera->vertical_fov, 39.3f * glm::pi<float>() / 180.0f, 1e-6f);
    EXPECT_FLOAT_EQ(scene.camera->aspect, 1.0f);
}

} // namespace
} // namespace wf
