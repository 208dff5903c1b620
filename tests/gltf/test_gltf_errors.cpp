// test_gltf_errors.cpp — bad glTF input: each must fail with one line, an
// InputError naming the file, the mesh or accessor, and the fault.
#include "gltf/gltf_document.h"

#include <limits>

namespace wf {
namespace {

TEST_F(GltfLoaderTest, MissingFileIsNamed) {
    expect_mentions(load_error((dir_ / "does_not_exist.gltf").string()),
                    {"does_not_exist.gltf", "no such file"});
}

TEST_F(GltfLoaderTest, MalformedJsonIsNamed) {
    const std::string path =
        write_text("malformed.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"meshes\": [");
    expect_mentions(load_error(path), {"malformed.gltf", "cannot load glTF"});
}

TEST_F(GltfLoaderTest, MalformedGlbIsNamed) {
    const std::string path =
        write_text("malformed.glb", std::string("glTF\x02\0\0\0", 8) + "not a real chunk header");
    expect_mentions(load_error(path), {"malformed.glb", "truncated GLB"});
}

TEST_F(GltfLoaderTest, MissingBufferFileIsNamed) {
    GltfDocument doc;
    doc.add_mesh_node("quad", triangle_primitive(doc.add_vec3(kQuad)));
    const std::string path = doc.write(dir_ / "missing_bin.gltf", BufferStorage::side_file);
    fs::remove(dir_ / "missing_bin.bin");
    expect_mentions(load_error(path), {"missing_bin.gltf", "missing_bin.bin"});
}

TEST_F(GltfLoaderTest, ShortBufferFileIsNamed) {
    GltfDocument doc;
    doc.add_mesh_node("quad", triangle_primitive(doc.add_vec3(kQuad)));
    const std::string path = doc.write(dir_ / "short_bin.gltf", BufferStorage::side_file);
    fs::resize_file(dir_ / "short_bin.bin", 20);
    expect_mentions(load_error(path), {"short_bin.gltf", "short_bin.bin"});
}

TEST_F(GltfLoaderTest, NanPositionIsNamed) {
    std::vector<float> positions = kTriangle;
    positions[4] = std::numeric_limits<float>::quiet_NaN();
    GltfDocument doc;
    doc.add_mesh_node("nan_mesh", triangle_primitive(doc.add_vec3(positions)));
    expect_mentions(load_error(doc.write(dir_ / "nan.gltf")),
                    {"nan.gltf", "mesh 'nan_mesh'", "POSITION 1", "NaN"});
}

TEST_F(GltfLoaderTest, InfinitePositionIsNamed) {
    std::vector<float> positions = kTriangle;
    positions[6] = -std::numeric_limits<float>::infinity();
    GltfDocument doc;
    doc.add_mesh_node("inf_mesh", triangle_primitive(doc.add_vec3(positions)));
    expect_mentions(load_error(doc.write(dir_ / "inf.gltf")),
                    {"inf.gltf", "mesh 'inf_mesh'", "POSITION 2", "infinite"});
}

// Found by tests/fuzz: corners this far apart are finite floats, but the BVH's
// bounds extent overflows to inf and its binning turned inf * 0 into an int.
TEST_F(GltfLoaderTest, PositionsNearFloatMaxAreNamed) {
    GltfDocument doc;
    doc.add_mesh_node("huge", triangle_primitive(doc.add_vec3({-3e38f, 0, 0, 3e38f, 0, 0, 0, 1, 0})));
    expect_mentions(load_error(doc.write(dir_ / "huge.gltf")), {"huge.gltf", "mesh 'huge'", "float range"});
}

TEST_F(GltfLoaderTest, IndexOutOfRangeIsNamed) {
    GltfDocument doc;
    json primitive = triangle_primitive(doc.add_vec3(kTriangle));
    primitive["indices"] = doc.add_indices(std::vector<uint16_t>{0, 1, 7});
    doc.add_mesh_node("stray_index", primitive);
    expect_mentions(load_error(doc.write(dir_ / "index.gltf")),
                    {"index.gltf", "mesh 'stray_index'", "index 7", "3 vertices"});
}

TEST_F(GltfLoaderTest, UnsupportedRequiredExtensionIsNamed) {
    GltfDocument doc;
    doc.add_mesh_node("quad", triangle_primitive(doc.add_vec3(kQuad)));
    doc.gltf["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    doc.gltf["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expect_mentions(load_error(doc.write(dir_ / "draco.gltf")),
                    {"draco.gltf", "KHR_draco_mesh_compression"});
}

TEST_F(GltfLoaderTest, AccessorPastItsBufferIsNamed) {
    GltfDocument doc;
    doc.add_mesh_node("overrun", triangle_primitive(doc.add_vec3(kTriangle)));
    doc.gltf["accessors"][0]["count"] = 30;
    expect_mentions(load_error(doc.write(dir_ / "overrun.gltf")),
                    {"overrun.gltf", "mesh 'overrun'", "accessor 0 (POSITION)", "runs past"});
}

TEST_F(GltfLoaderTest, BufferViewPastItsBufferIsNamed) {
    GltfDocument doc;
    doc.add_mesh_node("long_view", triangle_primitive(doc.add_vec3(kTriangle)));
    doc.gltf["bufferViews"][0]["byteOffset"] = 8;
    expect_mentions(
        load_error(doc.write(dir_ / "long_view.gltf")),
        {"long_view.gltf", "mesh 'long_view'", "bufferView 0", "runs past the end of buffer 0"});
}

TEST_F(GltfLoaderTest, WrongPositionFormatIsNamed) {
    GltfDocument doc;
    doc.add_mesh_node("flat", triangle_primitive(doc.add_vec3(kQuad)));
    doc.gltf["accessors"][0]["type"] = "VEC2";
    expect_mentions(load_error(doc.write(dir_ / "vec2.gltf")),
                    {"vec2.gltf", "mesh 'flat'", "POSITION", "VEC3 of FLOAT", "VEC2"});
}

TEST_F(GltfLoaderTest, SceneOfOnlyPointsHasNoTriangles) {
    GltfDocument doc;
    json primitive = triangle_primitive(doc.add_vec3(kQuad));
    primitive["mode"] = 0;
    doc.add_mesh_node("dots", primitive);
    expect_mentions(load_error(doc.write(dir_ / "points.gltf")), {"points.gltf", "no triangles"});
}

TEST_F(GltfLoaderTest, UnnamedMeshIsNamedByIndex) {
    GltfDocument doc;
    doc.add_mesh_node("quad", triangle_primitive(doc.add_vec3(kQuad)));
    doc.add_mesh_node("",
                      triangle_primitive(doc.add_vec3({0, 0, 0, 1, 0, 0, std::nanf(""), 1, 0})));
    expect_mentions(load_error(doc.write(dir_ / "unnamed.gltf")), {"unnamed.gltf: mesh 1: "});
}

} // namespace
} // namespace wf
