// test_gltf_instancing.cpp — a mesh that several nodes place is kept once and
// placed by instances (Scene::shared_meshes), and flattening those gives what
// the loader writes out when asked not to share; meshes that cannot be shared
// (one placement, an emitter, a transform with no inverse) are written out.
#include "gltf/gltf_document.h"
#include "scene/mesh_placement.h"
#include "scene/scene.h"

namespace wf {
namespace {

// A triangle facing +z, placed by `placements` nodes with these transforms.
GltfDocument placed_triangle(const std::vector<json>& placements, bool emits = false) {
    GltfDocument doc;
    json primitive = triangle_primitive(doc.add_vec3(kTriangle));
    primitive["attributes"]["NORMAL"] = doc.add_vec3({0, 0, 1, 0, 0, 1, 0, 0, 1});
    if (emits) {
        doc.gltf["materials"].push_back({{"name", "lamp"}, {"emissiveFactor", {1, 1, 1}}});
        primitive["material"] = 0;
    }
    doc.add_mesh_node("shared", primitive, placements.front());
    for (size_t i = 1; i < placements.size(); ++i) {
        json node = placements[i];
        node["mesh"] = 0;
        doc.add_root(node);
    }
    return doc;
}

// Every mesh several nodes place kept once, however small.
const LoadOptions kShareAll{-1, Instancing::All};

const std::vector<json> kThreePlacements = {
    json::object(), {{"translation", {5, 0, 0}}}, {{"scale", {-1, 2, 1}}, {"rotation", {0, 0.6, 0, 0.8}}}};

TEST_F(GltfLoaderTest, MeshPlacedByThreeNodesIsKeptOnce) {
    const std::string file = placed_triangle(kThreePlacements).write(dir_ / "three.gltf");
    // By default a mesh this small is written out: its copies are cheap, and render faster so.
    EXPECT_TRUE(load_gltf(file).instances.empty());
    const Scene scene = load_gltf(file, kShareAll);
    expect_well_formed(scene);
    EXPECT_EQ(scene.triangle_count(), 1u);
    ASSERT_EQ(scene.shared_meshes.size(), 1u);
    EXPECT_EQ(scene.shared_meshes[0].first, 0u);
    EXPECT_EQ(scene.shared_meshes[0].count, 1u);
    ASSERT_EQ(scene.instances.size(), 3u);
    EXPECT_EQ(scene.placed_triangle_count(), 3u);
    expect_near(scene.positions[1], {1, 0, 0}); // in the mesh's own space
    // Written out, in walk order: what flattening the instances gives.
    const Scene written_out = load_gltf(file, LoadOptions{-1, Instancing::Off});
    const Scene flat = flattened(scene);
    EXPECT_TRUE(written_out.instances.empty());
    ASSERT_EQ(written_out.triangle_count(), 3u);
    ASSERT_EQ(flat.triangle_count(), 3u);
    for (size_t corner = 0; corner < 9; ++corner) {
        expect_near(flat.positions[corner], written_out.positions[corner]);
        expect_near(flat.normals[corner], written_out.normals[corner]);
    }
    expect_near(scene.bounds().lo, written_out.bounds().lo, 1e-4f);
    expect_near(scene.bounds().hi, written_out.bounds().hi, 1e-4f);
}

TEST_F(GltfLoaderTest, MeshesThatCannotBeSharedAreWrittenOut) {
    // Placed once.
    Scene scene = load_gltf(placed_triangle({json::object()}).write(dir_ / "once.gltf"), kShareAll);
    EXPECT_TRUE(scene.instances.empty());
    // An emitter: each placement is a light of its own.
    scene = load_gltf(placed_triangle(kThreePlacements, true).write(dir_ / "lamps.gltf"), kShareAll);
    EXPECT_TRUE(scene.instances.empty());
    EXPECT_EQ(scene.triangle_count(), 3u);
    // A placement with no inverse is written out; the two others still share.
    std::vector<json> placements = kThreePlacements;
    placements[1]["scale"] = {0, 1, 1};
    scene = load_gltf(placed_triangle(placements).write(dir_ / "flat.gltf"), kShareAll);
    expect_well_formed(scene);
    EXPECT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.world_triangle_count(), 1u);
    EXPECT_EQ(scene.placed_triangle_count(), 3u);
}

// EXT_mesh_gpu_instancing: each instance a placement, its transform applied
// before the node's.
TEST_F(GltfLoaderTest, GpuInstancingPlacesEachInstance) {
    GltfDocument doc;
    json primitive = triangle_primitive(doc.add_vec3(kTriangle));
    const int translations = doc.add_vec3({0, 0, 0, 10, 0, 0, 0, 10, 0});
    const int scales = doc.add_vec3({1, 1, 1, 2, 2, 2, -1, 1, 1});
    // Unit quaternions x, y, z, w: none, none, a quarter turn about z the other way round (a negative
    // component, stored unnormalised, twice as long: no clamp at -1 may bend it).
    const float h = std::sqrt(0.5f);
    const int rotations = doc.add_vec4({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -2 * h, 2 * h});
    doc.add_mesh_node(
        "grass", primitive,
        {{"translation", {0, 0, 5}},
         {"extensions",
          {{"EXT_mesh_gpu_instancing",
            {{"attributes", {{"TRANSLATION", translations}, {"ROTATION", rotations}, {"SCALE", scales}}}}}}}});
    doc.gltf["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    const std::string file = doc.write(dir_ / "grass.gltf");
    const Scene scene = load_gltf(file, kShareAll);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    ASSERT_EQ(scene.instances.size(), 3u);
    const Scene flat = flattened(scene);
    ASSERT_EQ(flat.triangle_count(), 3u);
    expect_near(flat.positions[3 * 1 + 1], {12, 0, 5}); // instance 1: scaled by 2, then moved by (10, 0, 0) and (0, 0, 5)
    expect_near(flat.positions[3 * 2 + 0], {0, 10, 5});
    // Instance 2: corner (0, 1, 0) mirrored in x stays put, turned a quarter about -z goes to (1, 0, 0), then
    // moved; the mirror swaps corners 1 and 2, so it is the written-out triangle's corner 1.
    expect_near(flat.positions[3 * 2 + 1], {1, 10, 5});
    // Written out: the same triangles, the mirrored one's winding kept front-facing.
    const Scene written_out = load_gltf(file, LoadOptions{-1, Instancing::Off});
    ASSERT_EQ(written_out.triangle_count(), 3u);
    for (size_t t = 0; t < 3; ++t) EXPECT_GT(geometric_normal(written_out, t).z, 0.0f) << t;
    // An accessor of the wrong count is named.
    doc.gltf["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] = doc.add_vec3({1, 1, 1});
    expect_mentions(load_error(doc.write(dir_ / "bad.gltf")), {"bad.gltf", "EXT_mesh_gpu_instancing", "SCALE"});
    doc.gltf["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] = "scales";
    expect_mentions(load_error(doc.write(dir_ / "name.gltf")), {"name.gltf", "SCALE must be an accessor index"});
}

// The default keeps a mesh once where its copies beyond the first would hold
// kLargeSharedTriangles or more: a triangle placed that many times and one
// more, but not one placement fewer.
TEST_F(GltfLoaderTest, ByDefaultOnlyMeshesWithManyCopiesAreKeptOnce) {
    for (const size_t placements : {kLargeSharedTriangles, kLargeSharedTriangles + 1}) {
        GltfDocument doc;
        std::vector<float> translations;
        for (size_t i = 0; i < placements; ++i) translations.insert(translations.end(), {float(i), 0, 0});
        doc.add_mesh_node("grass", triangle_primitive(doc.add_vec3(kTriangle)),
                          {{"extensions",
                            {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", doc.add_vec3(translations)}}}}}}}});
        const Scene scene = load_gltf(doc.write(dir_ / "grass.gltf"));
        EXPECT_EQ(scene.placed_triangle_count(), placements);
        EXPECT_EQ(scene.instances.size(), placements > kLargeSharedTriangles ? placements : 0u) << placements;
    }
}

} // namespace
} // namespace wf
