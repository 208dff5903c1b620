// gltf_document.h — what the glTF loader tests share: GltfDocument, a glTF
// file built in code (JSON open to tests that break it, one binary buffer
// embedded or beside the file, or the whole as a GLB), the checks on what loading gives, and the
// fixture that gives each test its own scratch folder; where the real assets are.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "base/errors.h"
#include "gltf/gltf_loader.h"

#ifndef WF_SOURCE_DIR
#define WF_SOURCE_DIR "."
#endif

namespace wf {

namespace fs = std::filesystem;

// The real assets made by others, beside the checkout (see their INVENTORY.md).
inline const std::string kRealScenes = WF_SOURCE_DIR "/../shared/scenes-real/";
using nlohmann::json;

constexpr int kFloat = 5126;

// ---------------------------------------------------------------------------
// Writing test files

inline std::string base64(const std::vector<unsigned char>& bytes) {
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

    int add_vec4(const std::vector<float>& xyzw) { return add_accessor(xyzw, "VEC4", xyzw.size() / 4); }

    // VEC3 of normalized unsigned bytes (0..255 read as 0..1), as COLOR_0 may be.
    int add_normalized_vec3(const std::vector<uint8_t>& xyz) {
        const int accessor = add_accessor(xyz, "VEC3", xyz.size() / 3);
        gltf["accessors"][size_t(accessor)]["normalized"] = true;
        return accessor;
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
        json document = with_scene();
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

    // The document as a GLB: a JSON chunk, then the buffer as its BIN chunk.
    std::vector<unsigned char> glb() const {
        json document = with_scene();
        if (!blob_.empty()) document["buffers"] = json::array({{{"byteLength", blob_.size()}}});
        std::string text = document.dump();
        text.resize((text.size() + 3) / 4 * 4, ' ');
        std::vector<unsigned char> bin = blob_;
        bin.resize((bin.size() + 3) / 4 * 4, 0);
        std::vector<unsigned char> out;
        const auto word = [&out](size_t value) {
            for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<unsigned char>(value >> shift));
        };
        out.insert(out.end(), {'g', 'l', 'T', 'F'});
        word(2);
        word(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size()));
        word(text.size());
        out.insert(out.end(), {'J', 'S', 'O', 'N'});
        out.insert(out.end(), text.begin(), text.end());
        if (!bin.empty()) {
            word(bin.size());
            out.insert(out.end(), {'B', 'I', 'N', '\0'});
            out.insert(out.end(), bin.begin(), bin.end());
        }
        return out;
    }

private:
    json with_scene() const {
        json document = gltf;
        document["scene"] = 0;
        document["scenes"] = json::array({{{"nodes", roots_}}});
        return document;
    }

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
inline const std::vector<float> kQuad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
inline const std::vector<uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};
inline const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

inline json triangle_primitive(int positions) { return {{"attributes", {{"POSITION", positions}}}}; }

// ---------------------------------------------------------------------------
// Checking results

// The message of the InputError that loading throws; fails the test if none.
inline std::string load_error(const std::string& path, const LoadOptions& options = {}) {
    try {
        load_gltf(path, options);
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no InputError loading " << path;
    return {};
}

inline void expect_mentions(const std::string& message, std::initializer_list<std::string> parts) {
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& part : parts)
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

inline void expect_near(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
    EXPECT_LE(glm::length(actual - expected), tolerance)
        << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", "
        << expected.y << ", " << expected.z << ")";
}

inline glm::vec3 geometric_normal(const Scene& scene, size_t triangle) {
    const glm::vec3* p = &scene.positions[3 * triangle];
    return glm::cross(p[1] - p[0], p[2] - p[0]);
}

// The invariants every loaded scene keeps, whatever the file.
inline void expect_well_formed(const Scene& scene) {
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

inline uint32_t mesh_index(const Scene& scene, const std::string& name) {
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

} // namespace wf
