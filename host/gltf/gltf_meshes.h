// gltf_meshes.h — a glTF mesh's primitives as triangles in the mesh's own
// space: strips and fans unrolled with glTF's winding, attributes read per
// corner, tangents generated where the file has none (scene/tangents.h), and
// what cannot be rendered (points, lines, primitives without POSITION)
// counted for one warning per mesh.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/mesh_placement.h"
#include "scene/scene.h"

namespace wf {

// What a mesh holds that cannot be rendered, reported in one warning per mesh.
struct SkippedElements {
    size_t points = 0;
    size_t lines = 0;
    size_t primitives_without_position = 0;

    // `vertices`: the length of the primitive's vertex stream.
    void add(int mode, size_t vertices) {
        switch (mode) {
        case TINYGLTF_MODE_POINTS: points += vertices; break;
        case TINYGLTF_MODE_LINE: lines += vertices / 2; break;
        case TINYGLTF_MODE_LINE_LOOP: lines += vertices >= 2 ? vertices : 0; break;
        default: lines += vertices >= 2 ? vertices - 1 : 0; break; // TINYGLTF_MODE_LINE_STRIP
        }
    }

    std::string describe() const {
        std::string parts;
        const auto add_part = [&parts](size_t n, const char* noun) {
            if (n > 0) parts += (parts.empty() ? "" : ", ") + std::to_string(n) + " " + noun;
        };
        add_part(points, "points");
        add_part(lines, "lines");
        add_part(primitives_without_position, "primitives without POSITION");
        return parts.empty() ? parts : parts + " skipped";
    }
};

// The scene's material index for a primitive's glTF material (-1: none); the
// loader adds glTF's default material when one is first needed.
using MaterialIndex = std::function<uint32_t(int gltf_material, const std::string& where)>;

// Appends a primitive's triangles to `out`, or counts it in `skipped`.
// `materials` are the scene's, as `material_index` has them.
void append_primitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& where,
                      const MaterialIndex& material_index, const std::vector<SceneMaterial>& materials,
                      MeshTriangles& out, SkippedElements& skipped);

} // namespace wf
