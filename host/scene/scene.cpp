// scene.cpp — what scene.h declares beyond the structs: the bounds of placed
// triangles.
#include "scene/scene.h"

#include <cmath>
#include <limits>

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

std::vector<Bounds> shared_mesh_bounds(const Scene& scene) {
    std::vector<Bounds> boxes;
    for (const SharedMesh& mesh : scene.shared_meshes) boxes.push_back(triangle_bounds(scene, mesh.first, mesh.count));
    return boxes;
}

Bounds Scene::bounds() const {
    Bounds b = triangle_bounds(*this, 0, world_triangle_count());
    const std::vector<Bounds> meshes = shared_mesh_bounds(*this);
    for (const MeshInstance& instance : instances)
        b.grow(transformed_bounds(meshes[instance.mesh], instance.object_to_world));
    return b;
}

} // namespace wf
