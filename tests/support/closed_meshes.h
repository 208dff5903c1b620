// closed_meshes.h — closed triangle meshes whose faces share their vertices,
// and the points on them where a crack between triangles would show: every
// vertex, and points along every edge computed in float. For test_bvh.cpp and
// test_watertight.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace wf::test {

// Faces are triples of vertex indices; every edge is shared by two faces.
struct Mesh {
    std::vector<glm::vec3> vertices;
    std::vector<std::array<uint32_t, 3>> faces;

    std::vector<glm::vec3> corners() const { // three per face
        std::vector<glm::vec3> p;
        for (const auto& f : faces)
            for (uint32_t v : f) p.push_back(vertices[v]);
        return p;
    }
};

// An icosahedron subdivided `levels` times onto a sphere: 20 * 4^levels faces.
inline Mesh icosphere(int levels, float radius, glm::vec3 center) {
    const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> unit = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                                   {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (glm::vec3& v : unit) v = glm::normalize(v);
    std::vector<std::array<uint32_t, 3>> faces = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const std::pair<uint32_t, uint32_t> key = std::minmax(a, b);
            const auto found = midpoints.find(key);
            if (found != midpoints.end()) return found->second;
            unit.push_back(glm::normalize(unit[a] + unit[b]));
            const uint32_t index = static_cast<uint32_t>(unit.size() - 1);
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<std::array<uint32_t, 3>> finer;
        for (const auto& f : faces) {
            const uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    Mesh mesh{{}, faces};
    for (const glm::vec3& v : unit) mesh.vertices.push_back(center + radius * v);
    return mesh;
}

// The cube [-1, 1]^3 with n x n squares per face, two triangles each. A corner
// on a cube edge is computed by the same expression for every face it is on,
// and is one vertex of them all.
inline Mesh subdivided_cube(int n) {
    Mesh mesh;
    std::map<std::array<float, 3>, uint32_t> index;
    auto vertex = [&](const glm::vec3& v) {
        const uint32_t next = static_cast<uint32_t>(mesh.vertices.size());
        const auto [found, added] = index.emplace(std::array<float, 3>{v.x, v.y, v.z}, next);
        if (added) mesh.vertices.push_back(v);
        return found->second;
    };
    auto coordinate = [n](int i) { return static_cast<float>(2 * i - n) / static_cast<float>(n); };
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            auto at = [&](int i, int j) {
                glm::vec3 v;
                v[axis] = side ? 1.0f : -1.0f;
                v[(axis + 1) % 3] = coordinate(i);
                v[(axis + 2) % 3] = coordinate(j);
                return vertex(v);
            };
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < n; ++j) {
                    mesh.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                    mesh.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
                }
            }
        }
    }
    return mesh;
}

// A point to aim at, and the faces it lies on (as exactly as float allows).
struct CrackPoint {
    glm::vec3 point;
    std::vector<uint32_t> faces;
};

// Every vertex, and on every edge (each once) the points a + f (b - a) for
// f = 1/2 and 1/4, computed in float as anyone aiming at an edge would.
inline std::vector<CrackPoint> crack_points(const Mesh& mesh) {
    std::vector<CrackPoint> points(mesh.vertices.size());
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> edges;
    for (uint32_t f = 0; f < mesh.faces.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
            points[a].faces.push_back(f);
            edges[std::minmax(a, b)].push_back(f);
        }
    }
    for (size_t v = 0; v < mesh.vertices.size(); ++v) points[v].point = mesh.vertices[v];
    for (const auto& [edge, faces] : edges) {
        const glm::vec3 a = mesh.vertices[edge.first], b = mesh.vertices[edge.second];
        for (float f : {0.5f, 0.25f}) points.push_back(CrackPoint{a + f * (b - a), faces});
    }
    return points;
}

} // namespace wf::test
