// instance_bvh.cpp — see instance_bvh.h. The world-space triangles are one
// more placement, under the identity (whose arithmetic leaves a ray's bits as
// they are), so that the traversal knows one kind of leaf in the top tree.
#include "bvh/instance_bvh.h"

#include <cmath>
#include <stdexcept>

namespace wf {
namespace {

// A placement's box grown by 2^-18 of its largest coordinate: far beyond the
// few ulps by which a ray mapped into the mesh's space, rounded, moves a hit.
Bounds grown(const Bounds& b) {
    const glm::vec3 reach = glm::max(glm::abs(b.lo), glm::abs(b.hi));
    const float pad = 0x1p-18f * std::max(std::max(reach.x, reach.y), reach.z);
    return Bounds{b.lo - pad, b.hi + pad};
}

void store_rows(float (&rows)[3][4], const glm::dmat4& m) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) rows[r][c] = float(m[c][r]); // glm is column-major
}

// A mesh's tree appended to `into`: its node indices and BVH positions
// moved past those already there, its positions naming scene triangles from
// `first`. Returns the node that holds its box.
uint32_t append_tree(Bvh& into, const Bvh& tree, uint32_t first) {
    const auto node_base = uint32_t(into.nodes.size());
    const auto position_base = uint32_t(into.order.size());
    if (size_t{position_base} + tree.order.size() > size_t{WF_BVH_FIRST_MASK} + 1)
        throw std::invalid_argument("build_bvh: the shared meshes exceed what a leaf's child word can index");
    for (BvhNode node : tree.nodes) {
        for (uint32_t& child : node.child) {
            if (child == 0u) continue;
            child = (child & WF_BVH_LEAF) ? child + position_base : child + node_base;
        }
        into.nodes.push_back(node);
    }
    for (uint32_t t : tree.order) into.order.push_back(t == kNoTriangle ? t : t + first);
    into.depth = std::max(into.depth, tree.depth);
    return node_base;
}

} // namespace

Bvh build_scene_bvh(const Scene& scene) {
    if (scene.instances.empty()) return build_bvh(scene.positions);

    // The placements: the world-space triangles, if any, then the instances.
    struct Placement {
        size_t first, count; // scene triangles
        glm::dmat4 object_to_world;
        Bounds box;
    };
    std::vector<Placement> placements;
    if (scene.world_triangle_count() > 0)
        placements.push_back({0, scene.world_triangle_count(), glm::dmat4(1.0),
                              triangle_bounds(scene, 0, scene.world_triangle_count())});
    for (const MeshInstance& instance : scene.instances) {
        const SharedMesh& mesh = scene.shared_meshes[instance.mesh];
        placements.push_back({mesh.first, mesh.count, instance.object_to_world,
                              grown(transformed_bounds(triangle_bounds(scene, mesh.first, mesh.count),
                                                       instance.object_to_world))});
    }
    std::vector<Bounds> boxes;
    for (const Placement& p : placements) boxes.push_back(p.box);
    Bvh bvh = build_box_bvh(boxes);
    const std::vector<uint32_t> top_order = std::move(bvh.order);
    bvh.order.clear();

    // Each tree once, in the order of first placement.
    std::vector<uint32_t> root_of_first(scene.triangle_count() + 1, 0u); // by a tree's first scene triangle
    std::vector<bool> built(scene.triangle_count() + 1, false);
    for (const Placement& p : placements) {
        if (built[p.first]) continue;
        const std::vector<glm::vec3> corners(scene.positions.begin() + 3 * p.first,
                                             scene.positions.begin() + 3 * (p.first + p.count));
        root_of_first[p.first] = append_tree(bvh, build_bvh(corners), uint32_t(p.first));
        built[p.first] = true;
    }
    for (uint32_t i : top_order) {
        const Placement& p = placements[i];
        Instance instance{};
        store_rows(instance.object_to_world, p.object_to_world);
        store_rows(instance.world_to_object, glm::inverse(p.object_to_world));
        instance.root = root_of_first[p.first];
        instance.handedness = glm::determinant(glm::dmat3(p.object_to_world)) < 0.0 ? -1.0f : 1.0f;
        bvh.instances.push_back(instance);
    }
    return bvh;
}

} // namespace wf
