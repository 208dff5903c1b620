// scene.cpp — what scene.h declares beyond the structs: the bounds of placed
// triangles, and flattening a scene's instances into world space.
#include "scene/scene.h"

#include <algorithm>
#include <cmath>

#include "scene/mesh_placement.h"

namespace wf {

Bounds triangle_bounds(const Scene& scene, size_t first, size_t count) {
    Bounds b;
    for (size_t corner = 3 * first; corner < 3 * (first + count); ++corner) b.grow(scene.positions[corner]);
    return b;
}

Bounds transformed_bounds(const Bounds& box, const glm::dmat4& transform) {
    Bounds out;
    if (box.empty()) return out;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi = -lo;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p(corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                           corner & 4 ? box.hi.z : box.lo.z);
        const glm::dvec3 mapped(transform * glm::dvec4(p, 1.0));
        lo = glm::min(lo, mapped);
        hi = glm::max(hi, mapped);
    }
    for (int axis = 0; axis < 3; ++axis) { // outward: float(x) may round either way
        out.lo[axis] = std::nextafter(float(lo[axis]), -std::numeric_limits<float>::infinity());
        out.hi[axis] = std::nextafter(float(hi[axis]), std::numeric_limits<float>::infinity());
    }
    return out;
}

Bounds Scene::bounds() const {
    Bounds b = triangle_bounds(*this, 0, world_triangle_count());
    for (const MeshInstance& instance : instances) {
        const SharedMesh& mesh = shared_meshes[instance.mesh];
        b.grow(transformed_bounds(triangle_bounds(*this, mesh.first, mesh.count), instance.object_to_world));
    }
    return b;
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
