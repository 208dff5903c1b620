// mesh_placement.cpp — see mesh_placement.h.
#include "scene/mesh_placement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include <glm/gtc/matrix_inverse.hpp>

#include "scene/tangents.h"

namespace wf {
std::optional<glm::dvec3> direction_of(const glm::dvec3& v) {
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    return v / length;
}

void place_mesh(const MeshTriangles& mesh, const glm::dmat4& world, Scene& out) {
    const glm::dmat3 linear(world);
    const glm::dmat3 normal_matrix = glm::inverseTranspose(linear);
    const bool mirrored = glm::determinant(linear) < 0.0;
    const std::array<size_t, 3> order =
        mirrored ? std::array<size_t, 3>{0, 2, 1} : std::array<size_t, 3>{0, 1, 2};
    for (size_t triangle = 0; triangle < mesh.materials.size(); ++triangle) {
        std::array<glm::dvec3, 3> p;
        for (size_t k = 0; k < 3; ++k)
            p[k] = glm::dvec3(world * glm::dvec4(mesh.positions[3 * triangle + order[k]], 1.0));
        // Degenerate triangles stay (later stages handle them) with any unit normal.
        const glm::dvec3 geometric = direction_of(glm::cross(p[1] - p[0], p[2] - p[0])).value_or(glm::dvec3(0, 0, 1));
        for (size_t k = 0; k < 3; ++k) {
            const size_t corner = 3 * triangle + order[k];
            const glm::vec3 unit_normal(direction_of(normal_matrix * glm::dvec3(mesh.normals[corner])).value_or(geometric));
            out.positions.push_back(glm::vec3(p[k]));
            out.normals.push_back(unit_normal);
            // Scenes built in code have no texture coordinates, tangents or colours.
            if (mesh.uv0.empty()) continue;
            out.uv0.push_back(mesh.uv0[corner]);
            out.uv1.push_back(mesh.uv1[corner]);
            out.colors.push_back(mesh.colors[corner]);
            const glm::vec4 t = mesh.tangents[corner];
            out.tangents.push_back(
                orthogonal_tangent(unit_normal, glm::vec3(linear * glm::dvec3(t)), mirrored ? -t.w : t.w));
        }
        out.triangle_material.push_back(mesh.materials[triangle]);
        out.triangle_mesh.push_back(mesh.name_index);
    }
}

MeshTriangles mesh_of(const Scene& scene, size_t first, size_t count) {
    MeshTriangles mesh;
    // Scenes built in code have no texture coordinates, tangents or colours: nor has their mesh.
    const auto corners = [&](const auto& v) {
        return v.empty() ? std::decay_t<decltype(v)>() : std::decay_t<decltype(v)>(v.begin() + 3 * first, v.begin() + 3 * (first + count));
    };
    mesh.positions = corners(scene.positions);
    mesh.normals = corners(scene.normals);
    mesh.uv0 = corners(scene.uv0);
    mesh.uv1 = corners(scene.uv1);
    mesh.tangents = corners(scene.tangents);
    mesh.colors = corners(scene.colors);
    mesh.materials.assign(scene.triangle_material.begin() + first, scene.triangle_material.begin() + first + count);
    mesh.name_index = count > 0 ? scene.triangle_mesh[first] : 0u;
    return mesh;
}

Scene flattened(const Scene& scene) {
    Scene flat = scene;
    flat.shared_meshes.clear();
    flat.instances.clear();
    if (scene.shared_meshes.empty()) return flat;
    const size_t world = scene.world_triangle_count();
    const auto keep_corners = [world](auto& v) { v.resize(std::min(v.size(), 3 * world)); };
    keep_corners(flat.positions);
    keep_corners(flat.normals);
    keep_corners(flat.uv0);
    keep_corners(flat.uv1);
    keep_corners(flat.tangents);
    keep_corners(flat.colors);
    flat.triangle_material.resize(world);
    flat.triangle_mesh.resize(world);
    std::vector<MeshTriangles> meshes;
    for (const SharedMesh& mesh : scene.shared_meshes) meshes.push_back(mesh_of(scene, mesh.first, mesh.count));
    for (const MeshInstance& instance : scene.instances)
        place_mesh(meshes[instance.mesh], instance.object_to_world, flat);
    return flat;
}

} // namespace wf
