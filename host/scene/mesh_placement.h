// mesh_placement.h — a mesh's triangles in its own space, and their placement
// in a scene's world space: what the glTF loader does for a mesh that one node
// places, and what flattening a scene's shared meshes does for each of their
// instances.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace wf {

// One mesh's triangles in the mesh's own space, built once however many
// nodes place it.
struct MeshTriangles {
    std::vector<glm::vec3> positions; // three per triangle
    std::vector<glm::vec3> normals;   // three per triangle; zero where the file has none
    std::vector<glm::vec2> uv0, uv1;  // three per triangle; zero where the file has none
    std::vector<glm::vec4> tangents;  // three per triangle; the file's, or generated (tangents.h)
    std::vector<glm::vec4> colors;    // three per triangle; COLOR_0, white where the file has none
    std::vector<uint32_t> materials;  // one per triangle, index into Scene::materials
    uint32_t name_index = 0;          // into Scene::mesh_names
};

// Appends the mesh's triangles to `out`, mapped by `world`. A mirroring
// transform swaps two corners so counter-clockwise stays the front face;
// normals go through the inverse transpose, and fall back to the geometric
// normal where the file has none or they do not survive the transform;
// tangents move with the surface, a mirror flipping their handedness. The
// caller has checked that the mapped corners stay in float range
// (kMaxCoordinate).
void place_mesh(const MeshTriangles& mesh, const glm::dmat4& world, Scene& out);

// The scene's triangles [first, first + count) as a mesh of their own (a
// shared mesh's, to be placed again).
MeshTriangles mesh_of(const Scene& scene, size_t first, size_t count);

// The scene with every instance of a shared mesh written out in world space,
// as the loader writes a mesh placed once: for devices whose traversal has
// one level (a GPU's), and for comparing the two.
Scene flattened(const Scene& scene);

// `v` scaled to unit length, or nothing where it has no direction (zero or not
// finite).
std::optional<glm::dvec3> direction_of(const glm::dvec3& v);

// A quarter of float range, so that the BVH's centroids (a sum of three
// corners) and bounds extents (a difference of two) stay finite: past it the
// builder computed inf * 0 (found by fuzzing).
constexpr double kMaxCoordinate = double(std::numeric_limits<float>::max()) / 4.0;

} // namespace wf
