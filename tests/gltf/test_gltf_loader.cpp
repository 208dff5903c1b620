// test_gltf_loader.cpp — wf::load_gltf against small glTF files written here
// (each bad input must fail with a one-line InputError naming the file, the
// mesh and the fault; each good one must give the geometry glTF defines), the
// real assets in shared/scenes-real (every one loads, with the inventory's
// triangle count, finite positions and unit normals), and
// scenes/cornell-box.gltf.

#include "gltf/gltf_loader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "base/errors.h"

#ifndef WF_SOURCE_DIR
#define WF_SOURCE_DIR "."
#endif

namespace wf {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kRealScenes = WF_SOURCE_DIR "/../shared/scenes-real/";

constexpr int kFloat = 5126;

// ---------------------------------------------------------------------------
// Writing test files

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char alphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t left = bytes.size() - i;
        const uint32_t chunk = uint32_t(bytes[i]) << 16 |
                               (left > 1 ? uint32_t(bytes[i + 1]) << 8 : 0u) |
                               (left > 2 ? uint32_t(bytes[i + 2]) : 0u);
        out += alphabet[chunk >> 18 & 63];
        out += alphabet[chunk >> 12 & 63];
        out += left > 1 ? alphabet[chunk >> 6 & 63] : '=';
        out += left > 2 ? alphabet[chunk & 63] : '=';
    }
    return out;
}

template <typename T>
int component_type_of() {
    if constexpr (std::is_same_v<T, uint8_t>)
        return 5121;
    else if constexpr (std::is_same_v<T, uint16_t>)
        return 5123;
    else if constexpr (std::is_same_v<T, uint32_t>)
        return 5125;
    else
        return kFloat;
}

enum class BufferStorage { embedded, side_file };

// A glTF document built in code: its JSON, open to tests that want to break
// it, and one binary buffer that write() embeds or puts beside the file.
class GltfDocument {
public:
    json gltf = {{"asset", {{"version", "2.0"}}}};

    int add_vec3(const std::vector<float>& xyz) {
        return add_accessor(xyz, "VEC3", xyz.size() / 3);
    }

    template <typename T>
    int add_indices(const std::vector<T>& indices) {
        return add_accessor(indices, "SCALAR", indices.size());
    }

    // A mesh of one primitive, instanced by a new root node; returns the node.
    int add_mesh_node(const std::string& name, const json& primitive, json node = json::object()) {
        gltf["meshes"].push_back({{"name", name}, {"primitives", json::array({primitive})}});
        node["mesh"] = gltf["meshes"].size() - 1;
        return add_root(node);
    }

    int add_node(const json& node) {
        gltf["nodes"].push_back(node);
        return int(gltf["nodes"].size()) - 1;
    }

    int add_root(const json& node) {
        roots_.push_back(add_node(node));
        return roots_.back();
    }

    std::string write(const fs::path& path, BufferStorage storage = BufferStorage::embedded) const {
        json document = gltf;
        document["scene"] = 0;
        document["scenes"] = json::array({{{"nodes", roots_}}});
        if (!blob_.empty()) {
            std::string uri = "data:application/octet-stream;base64," + base64(blob_);
            if (storage == BufferStorage::side_file) {
                uri = path.stem().string() + ".bin";
                std::ofstream(path.parent_path() / uri, std::ios::binary)
                    .write(reinterpret_cast<const char*>(blob_.data()),
                           std::streamsize(blob_.size()));
            }
            document["buffers"] = json::array({{{"byteLength", blob_.size()}, {"uri", uri}}});
        }
        std::ofstream(path) << document.dump(1);
        return path.string();
    }

private:
    template <typename T>
    int add_accessor(const std::vector<T>& values, const char* type, size_t count) {
        blob_.resize((blob_.size() + 3) / 4 * 4, 0);
        gltf["bufferViews"].push_back({{"buffer", 0},
                                       {"byteOffset", blob_.size()},
                                       {"byteLength", values.size() * sizeof(T)}});
        const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
        blob_.insert(blob_.end(), bytes, bytes + values.size() * sizeof(T));
        gltf["accessors"].push_back({{"bufferView", gltf["bufferViews"].size() - 1},
                                     {"componentType", component_type_of<T>()},
                                     {"count", count},
                                     {"type", type}});
        return int(gltf["accessors"].size()) - 1;
    }

    std::vector<unsigned char> blob_;
    std::vector<int> roots_;
};

// A unit quad in z = 0, counter-clockwise seen from +z.
const std::vector<float> kQuad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::vector<uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};
const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

json triangle_primitive(int positions) { return {{"attributes", {{"POSITION", positions}}}}; }

// ---------------------------------------------------------------------------
// Checking results

// The message of the InputError that loading throws; fails the test if none.
std::string load_error(const std::string& path, const LoadOptions& options = {}) {
    try {
        load_gltf(path, options);
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no InputError loading " << path;
    return {};
}

void expect_mentions(const std::string& message, std::initializer_list<std::string> parts) {
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& part : parts)
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

void expect_near(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
    EXPECT_LE(glm::length(actual - expected), tolerance)
        << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", "
        << expected.y << ", " << expected.z << ")";
}

glm::vec3 geometric_normal(const Scene& scene, size_t triangle) {
    const glm::vec3* p = &scene.positions[3 * triangle];
    return glm::cross(p[1] - p[0], p[2] - p[0]);
}

// The invariants every loaded scene keeps, whatever the file.
void expect_well_formed(const Scene& scene) {
    const size_t n = scene.triangle_count();
    ASSERT_GT(n, 0u);
    ASSERT_EQ(scene.positions.size(), 3 * n);
    ASSERT_EQ(scene.normals.size(), 3 * n);
    ASSERT_EQ(scene.triangle_mesh.size(), n);
    for (size_t t = 0; t < n; ++t) {
        ASSERT_LT(scene.triangle_material[t], scene.materials.size());
        ASSERT_LT(scene.triangle_mesh[t], scene.mesh_names.size());
    }
    for (size_t i = 0; i < 3 * n; ++i) {
        const glm::vec3& p = scene.positions[i];
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            << "corner " << i;
        ASSERT_NEAR(glm::length(scene.normals[i]), 1.0f, 1e-4f) << "corner " << i;
    }
}

uint32_t mesh_index(const Scene& scene, const std::string& name) {
    const auto it = std::find(scene.mesh_names.begin(), scene.mesh_names.end(), name);
    EXPECT_NE(it, scene.mesh_names.end()) << "no mesh " << name;
    return uint32_t(it - scene.mesh_names.begin());
}

class GltfLoaderTest : public ::testing::Test {
protected:
    void SetUp() override {
        const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        dir_ =
            fs::temp_directory_path() / ("wf_gltf_loader_" + std::to_string(getpid()) + "_" + test);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }

    std::string write_text(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name, std::ios::binary) << text;
        return (dir_ / name).string();
    }

    fs::path dir_;
};

// ---------------------------------------------------------------------------
// Bad input

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
    expect_mentions(load_error(path), {"malformed.glb", "cannot load GLB"});
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

// ---------------------------------------------------------------------------
// Geometry

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
    EXPECT_EQ(scene.triangle_count(), 2u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "mesh 'mixed': 4 points, 3 lines skipped");
    EXPECT_EQ(scene.mesh_names, std::vector<std::string>{"mixed"});
}

// ---------------------------------------------------------------------------
// Materials and extensions

TEST_F(GltfLoaderTest, EmissiveStrengthMultipliesTheFactor) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    doc.gltf["materials"] = {
        {{"name", "lamp"},
         {"emissiveFactor", {0.5, 0.25, 1.0}},
         {"doubleSided", true},
         {"pbrMetallicRoughness", {{"baseColorFactor", {1.5, -0.5, 0.3, 1.0}}}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}},
        {{"name", "dim"}, {"emissiveFactor", {0.5, 0.25, 1.0}}}};
    const int positions = doc.add_vec3(kTriangle);
    for (int material : {0, 1}) {
        json primitive = triangle_primitive(positions);
        primitive["material"] = material;
        doc.add_mesh_node("m" + std::to_string(material), primitive);
    }
    const Scene scene = load_gltf(doc.write(dir_ / "emissive.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_TRUE(scene.warnings.empty());
    EXPECT_EQ(scene.materials[0].name, "lamp");
    EXPECT_TRUE(scene.materials[0].double_sided);
    expect_near(scene.materials[0].emission, {2, 1, 4});
    expect_near(scene.materials[0].base_color, {1, 0, 0.3f}); // clamped to [0, 1]
    EXPECT_FALSE(scene.materials[1].double_sided);
    expect_near(scene.materials[1].emission, {0.5f, 0.25f, 1});
    EXPECT_EQ(scene.triangle_material, (std::vector<uint32_t>{0, 1}));
}

TEST_F(GltfLoaderTest, PrimitivesWithoutMaterialShareOneDefault) {
    GltfDocument doc;
    doc.gltf["materials"] = {
        {{"name", "red"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}}};
    const int positions = doc.add_vec3(kTriangle);
    json red = triangle_primitive(positions);
    red["material"] = 0;
    doc.add_mesh_node("a", triangle_primitive(positions));
    doc.add_mesh_node("b", red);
    doc.add_mesh_node("c", triangle_primitive(positions));
    const Scene scene = load_gltf(doc.write(dir_ / "default.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.materials.size(), 2u);
    expect_near(scene.materials[1].base_color, {1, 1, 1});
    expect_near(scene.materials[1].emission, {0, 0, 0});
    EXPECT_EQ(scene.triangle_material, (std::vector<uint32_t>{1, 0, 1}));
    EXPECT_EQ(scene.triangle_mesh, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(scene.mesh_names, (std::vector<std::string>{"a", "b", "c"}));
}

// Textures are test_texture.cpp's; KHR_texture_transform is now supported.
TEST_F(GltfLoaderTest, UnknownExtensionsWarnButLoad) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_texture_transform"};
    doc.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}}};
    json primitive = triangle_primitive(doc.add_vec3(kTriangle));
    primitive["material"] = 0;
    doc.add_mesh_node("textured", primitive);
    const Scene scene = load_gltf(doc.write(dir_ / "textured.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "extensions not supported, ignored: KHR_materials_clearcoat");
}

TEST_F(GltfLoaderTest, MetallicRoughnessTransmissionIorAndSpecularAreRead) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_specular"};
    doc.gltf["materials"] = {
        {{"name", "gold"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {1.0, 0.71, 0.29, 1.0}}, {"metallicFactor", 1.0}, {"roughnessFactor", 0.25}}}},
        {{"name", "glass"},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}},
         {"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}, {"KHR_materials_ior", {{"ior", 1.33}}}}}},
        {{"name", "matte"},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 2.0}}},
         {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}}};
    const int positions = doc.add_vec3(kTriangle);
    for (int material : {0, 1, 2, -1}) {
        json primitive = triangle_primitive(positions);
        if (material >= 0) primitive["material"] = material;
        doc.add_mesh_node("m" + std::to_string(material + 1), primitive);
    }
    const Scene scene = load_gltf(doc.write(dir_ / "materials.gltf"));
    expect_well_formed(scene);
    EXPECT_TRUE(scene.warnings.empty());
    ASSERT_EQ(scene.materials.size(), 4u);
    const SceneMaterial &gold = scene.materials[0], &glass = scene.materials[1], &matte = scene.materials[2],
                        &fallback = scene.materials[3];
    expect_near(gold.base_color, {1.0f, 0.71f, 0.29f});
    EXPECT_FLOAT_EQ(gold.metallic, 1.0f);
    EXPECT_FLOAT_EQ(gold.roughness, 0.25f);
    EXPECT_FLOAT_EQ(gold.transmission, 0.0f);
    EXPECT_FLOAT_EQ(gold.ior, 1.5f);     // KHR_materials_ior's default
    EXPECT_FLOAT_EQ(gold.specular, 1.0f); // KHR_materials_specular's default
    EXPECT_FLOAT_EQ(glass.transmission, 1.0f);
    EXPECT_FLOAT_EQ(glass.ior, 1.33f);
    EXPECT_FLOAT_EQ(glass.roughness, 0.0f);
    EXPECT_FLOAT_EQ(matte.roughness, 1.0f); // clamped to [0, 1]
    EXPECT_FLOAT_EQ(matte.specular, 0.0f);
    // glTF 2.0's default material: white, metallic 1, roughness 1.
    expect_near(fallback.base_color, {1, 1, 1});
    EXPECT_FLOAT_EQ(fallback.metallic, 1.0f);
    EXPECT_FLOAT_EQ(fallback.roughness, 1.0f);
}

TEST_F(GltfLoaderTest, IorBelowOneIsNamed) {
    GltfDocument doc;
    doc.gltf["materials"] = {{{"name", "odd"}, {"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}}};
    json primitive = triangle_primitive(doc.add_vec3(kTriangle));
    primitive["material"] = 0;
    doc.add_mesh_node("m", primitive);
    expect_mentions(load_error(doc.write(dir_ / "ior.gltf")), {"ior.gltf", "material 'odd'", "ior 0.5"});
}

TEST_F(GltfLoaderTest, SkinsMorphTargetsAndAnimationsAreReportedOnce) {
    GltfDocument doc;
    const int positions = doc.add_vec3(kTriangle);
    json primitive = triangle_primitive(positions);
    primitive["targets"] = {{{"POSITION", positions}}, {{"POSITION", positions}}};
    doc.add_mesh_node("a", primitive);
    doc.add_mesh_node("b", primitive);
    doc.gltf["skins"] = {{{"joints", {0}}}};
    doc.gltf["animations"] = {{{"channels", json::array()}, {"samplers", json::array()}}};
    const Scene scene = load_gltf(doc.write(dir_ / "animated.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.warnings.size(), 3u);
    expect_mentions(scene.warnings[0], {"1 skin", "bind pose"});
    expect_mentions(scene.warnings[1], {"morph targets", "2 primitive"});
    expect_mentions(scene.warnings[2], {"1 animation"});
}

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

TEST(GltfRealAssets, NegativeScaleKeepsFrontFacesOutward) {
    const Scene scene = load_real("NegativeScaleTest/NegativeScaleTest.gltf");
    expect_well_formed(scene);
    EXPECT_EQ(scene.triangle_count(), 7724u);
    size_t disagreeing = 0;
    for (size_t t = 0; t < scene.triangle_count(); ++t)
        if (glm::dot(geometric_normal(scene, t), scene.normals[3 * t]) < 0.0f) ++disagreeing;
    EXPECT_EQ(disagreeing, 0u);
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
        EXPECT_EQ(scene.triangle_count(), entry.triangles);
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
