// test_gltf_geometry.cpp — the triangles glTF defines: index widths, strips
// and fans, node transforms and their composition, winding under negative
// scale, normals filled in where a file has none.
#include "gltf/gltf_document.h"

namespace wf {
namespace {

TEST_F(GltfLoaderTest, IndexWidthsAndNonIndexedGiveTheSameTriangles) {
    const auto load_quad = [this](const std::string& name, const auto& indices) {
        GltfDocument doc;
        json primitive = triangle_primitive(doc.add_vec3(kQuad));
        primitive["indices"] = doc.add_indices(indices);
        doc.add_mesh_node("quad", primitive);
        return load_gltf(doc.write(dir_ / name));
    };
    const Scene u8 =
        load_quad("u8.gltf", std::vector<uint8_t>(kQuadIndices.begin(), kQuadIndices.end()));
    const Scene u16 =
        load_quad("u16.gltf", std::vector<uint16_t>(kQuadIndices.begin(), kQuadIndices.end()));
    const Scene u32 = load_quad("u32.gltf", kQuadIndices);

    std::vector<float> unrolled;
    for (uint32_t index : kQuadIndices)
        unrolled.insert(unrolled.end(), kQuad.begin() + 3 * index, kQuad.begin() + 3 * index + 3);
    GltfDocument doc;
    doc.add_mesh_node("quad", triangle_primitive(doc.add_vec3(unrolled)));
    const Scene plain = load_gltf(doc.write(dir_ / "plain.gltf"));

    expect_well_formed(u32);
    ASSERT_EQ(u32.triangle_count(), 2u);
    EXPECT_EQ(u8.positions, u32.positions);
    EXPECT_EQ(u16.positions, u32.positions);
    EXPECT_EQ(plain.positions, u32.positions);
    EXPECT_EQ(plain.normals, u32.normals);
}

TEST_F(GltfLoaderTest, StripsAndFansUnrollCounterClockwise) {
    // Five vertices each of a zig-zag strip and a convex fan, all facing +z.
    const std::vector<float> strip = {0, 1, 0, 0, 0, 0, 1, 1, 0, 1, 0, 0, 2, 1, 0};
    const std::vector<float> fan = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 1, 0};
    GltfDocument doc;
    json strip_primitive = triangle_primitive(doc.add_vec3(strip));
    strip_primitive["mode"] = 5;
    json fan_primitive = triangle_primitive(doc.add_vec3(fan));
    fan_primitive["mode"] = 6;
    doc.add_mesh_node("strip", strip_primitive);
    doc.add_mesh_node("fan", fan_primitive);
    const Scene scene = load_gltf(doc.write(dir_ / "strips.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 6u);
    for (size_t t = 0; t < 6; ++t)
        EXPECT_GT(geometric_normal(scene, t).z, 0.0f) << "triangle " << t;
}

TEST_F(GltfLoaderTest, NegativeScaleFlipsTheWinding) {
    GltfDocument doc;
    json primitive = triangle_primitive(doc.add_vec3(kTriangle));
    primitive["attributes"]["NORMAL"] = doc.add_vec3({0, 0, 1, 0, 0, 1, 0, 0, 1});
    doc.add_mesh_node("mirrored", primitive, {{"scale", {-1, 1, 1}}});
    const Scene scene = load_gltf(doc.write(dir_ / "mirror.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 1u);
    expect_near(scene.normals[0], {0, 0, 1});
    EXPECT_GT(glm::dot(geometric_normal(scene, 0), scene.normals[0]), 0.0f);
}

TEST_F(GltfLoaderTest, TrsAndMatrixGiveTheSamePositions) {
    // T(1, 2, 3) R(90 degrees about z) S(2, 3, 4), once as TRS, once as its matrix.
    const double half = std::sqrt(0.5);
    const json trs = {
        {"translation", {1, 2, 3}}, {"rotation", {0, 0, half, half}}, {"scale", {2, 3, 4}}};
    const json matrix = {{"matrix", {0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1}}};
    GltfDocument doc;
    const int positions = doc.add_vec3(kQuad);
    doc.add_mesh_node("trs", triangle_primitive(positions), trs);
    doc.add_mesh_node("matrix", triangle_primitive(positions), matrix);
    const Scene scene = load_gltf(doc.write(dir_ / "transforms.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 2u);
    for (size_t i = 0; i < 3; ++i) expect_near(scene.positions[i], scene.positions[3 + i]);
    // (1, 0, 0) scaled to (2, 0, 0), rotated to (0, 2, 0), moved to (1, 4, 3).
    expect_near(scene.positions[1], {1, 4, 3});
    expect_near(scene.normals[0], {0, 0, 1});
}

TEST_F(GltfLoaderTest, ChildTransformsComposeWithTheirParents) {
    GltfDocument doc;
    doc.gltf["meshes"].push_back(
        {{"name", "child"},
         {"primitives", json::array({triangle_primitive(doc.add_vec3(kTriangle))})}});
    const int child = doc.add_node({{"mesh", 0}, {"scale", {2, 2, 2}}});
    doc.add_root({{"translation", {10, 0, 0}}, {"children", {child}}});
    const Scene scene = load_gltf(doc.write(dir_ / "hierarchy.gltf"));
    expect_well_formed(scene);
    expect_near(scene.positions[1], {12, 0, 0});
    expect_near(scene.positions[2], {10, 2, 0});
}

TEST_F(GltfLoaderTest, MissingOrZeroNormalsBecomeGeometricNormals) {
    GltfDocument doc;
    // In the xz plane, counter-clockwise seen from -y.
    const std::vector<float> floor_triangle = {0, 0, 0, 1, 0, 0, 0, 0, 1};
    doc.add_mesh_node("no_normals", triangle_primitive(doc.add_vec3(floor_triangle)));
    json zero_normals = triangle_primitive(doc.add_vec3(floor_triangle));
    zero_normals["attributes"]["NORMAL"] = doc.add_vec3(std::vector<float>(9, 0.0f));
    doc.add_mesh_node("zero_normals", zero_normals);
    doc.add_mesh_node("degenerate", triangle_primitive(doc.add_vec3({0, 0, 0, 1, 1, 1, 2, 2, 2})));
    const Scene scene = load_gltf(doc.write(dir_ / "normals.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 3u);
    for (size_t i = 0; i < 6; ++i) expect_near(scene.normals[i], {0, -1, 0});
}

TEST_F(GltfLoaderTest, PointsAndLinesAreSkippedWithOneWarningPerMesh) {
    GltfDocument doc;
    const int positions = doc.add_vec3(kQuad);
    json points = triangle_primitive(positions);
    points["mode"] = 0;
    json line_strip = triangle_primitive(positions);
    line_strip["mode"] = 3;
    doc.gltf["meshes"].push_back(
        {{"name", "mixed"}, {"primitives", {points, line_strip, triangle_primitive(positions)}}});
    doc.add_root({{"mesh", 0}});
    doc.add_root({{"mesh", 0}}); // a second instance must not repeat the warning
    const Scene scene = load_gltf(doc.write(dir_ / "mixed.gltf"));
    expect_well_formed(scene);
    EXPECT_EQ(scene.placed_triangle_count(), 2u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "mesh 'mixed': 4 points, 3 lines skipped");
    EXPECT_EQ(scene.mesh_names, std::vector<std::string>{"mixed"});
}

} // namespace
} // namespace wf
