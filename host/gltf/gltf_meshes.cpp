// gltf_meshes.cpp — see gltf_meshes.h.
#include "gltf/gltf_meshes.h"

#include <numeric>

#include "gltf/gltf_accessors.h"
#include "gltf/gltf_diagnostics.h"
#include "scene/tangents.h"

namespace wf {
namespace {

bool is_triangle_mode(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// Three vertex indices per triangle, strips and fans unrolled with the
// winding glTF 2.0 §3.7.2.1 gives them, so the front face stays the same.
std::vector<uint32_t> triangle_corners(int mode, const std::vector<uint32_t>& v) {
    std::vector<uint32_t> corners;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        corners.assign(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 3 * 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 0; i + 2 < v.size(); ++i) {
            const size_t odd = i % 2;
            corners.insert(corners.end(), {v[i], v[i + 1 + odd], v[i + 2 - odd]});
        }
    } else { // TINYGLTF_MODE_TRIANGLE_FAN
        for (size_t i = 0; i + 2 < v.size(); ++i)
            corners.insert(corners.end(), {v[i + 1], v[i + 2], v[0]});
    }
    return corners;
}

} // namespace

using tinygltf::Model;

void append_primitive(const Model& model, const tinygltf::Primitive& primitive, const std::string& where,
                      const MaterialIndex& material_index, const std::vector<SceneMaterial>& materials,
                      MeshTriangles& out, SkippedElements& skipped) {
    const auto attribute = [&primitive](const char* name) {
        const auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    const int position_accessor = attribute("POSITION");
    if (primitive.mode < TINYGLTF_MODE_POINTS || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        fail(where, "unknown primitive mode " + std::to_string(primitive.mode));
    // glTF 2.0 §3.7.2.1: a primitive without positions is not rendered.
    if (position_accessor < 0) {
        ++skipped.primitives_without_position;
        return;
    }
    if (!is_triangle_mode(primitive.mode)) {
        const bool indexed = primitive.indices >= 0;
        skipped.add(primitive.mode,
                    find_accessor(model, indexed ? primitive.indices : position_accessor,
                                  where, indexed ? "indices" : "POSITION")
                        .count);
        return;
    }

    const std::vector<glm::vec3> positions =
        read_vec3_attribute(model, position_accessor, where, "POSITION");
    check_finite(positions, where);
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    if (const int normal_accessor = attribute("NORMAL"); normal_accessor >= 0) {
        normals = read_vec3_attribute(model, normal_accessor, where, "NORMAL");
        if (normals.size() != positions.size())
            fail(where, "NORMAL has " + std::to_string(normals.size()) +
                            " elements but POSITION has " + std::to_string(positions.size()));
    }
    std::vector<uint32_t> vertices(positions.size());
    if (primitive.indices >= 0)
        vertices = read_indices(model, primitive.indices, where);
    else
        std::iota(vertices.begin(), vertices.end(), 0u);
    for (uint32_t vertex : vertices)
        if (vertex >= positions.size())
            fail(where, "index " + std::to_string(vertex) + " out of range (" +
                            std::to_string(positions.size()) + " vertices)");

    const uint32_t material = material_index(primitive.material, where);
    const std::vector<glm::vec2> uv0 = read_texcoords(model, attribute("TEXCOORD_0"), positions.size(), where, "TEXCOORD_0");
    const std::vector<glm::vec2> uv1 = read_texcoords(model, attribute("TEXCOORD_1"), positions.size(), where, "TEXCOORD_1");
    const std::vector<glm::vec4> colors = read_colors(model, attribute("COLOR_0"), positions.size(), where);
    const std::vector<uint32_t> corners = triangle_corners(primitive.mode, vertices);
    // Generated from the UV set the material's normal map reads.
    const int tangent_accessor = attribute("TANGENT");
    const bool normal_map_uv1 = materials[material].textures[WF_TEXTURE_NORMAL].texcoord == 1u;
    const std::vector<glm::vec4> tangents =
        tangent_accessor >= 0 ? read_tangents(model, tangent_accessor, positions.size(), where)
                              : generate_tangents(positions, normals, normal_map_uv1 ? uv1 : uv0, corners);
    for (uint32_t corner : corners) {
        out.positions.push_back(positions[corner]);
        out.normals.push_back(normals[corner]);
        out.uv0.push_back(uv0[corner]);
        out.uv1.push_back(uv1[corner]);
        out.tangents.push_back(tangents[corner]);
        out.colors.push_back(colors[corner]);
    }
    out.materials.resize(out.positions.size() / 3, material);
}

} // namespace wf
