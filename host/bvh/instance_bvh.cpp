// instance_bvh.cpp — see instance_bvh.h. The world-space triangles are one
// more placement, under the identity (whose arithmetic keeps a ray's bits but
// for the sign of a zero), so that the traversal knows one kind of leaf in
// the top tree.
#include "bvh/instance_bvh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wf {
namespace {

glm::dmat4 float_matrix(const float (&rows)[3][4]) {
    glm::dmat4 m(1.0);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = rows[r][c]; // glm is column-major
    return m;
}

void store_rows(float (&rows)[3][4], const glm::dmat4& m) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) rows[r][c] = float(m[c][r]);
}

// How far a placement's stored maps stretch a vector there and back: the
// largest row of |M| |W| 1 for their linear parts, at least 1.
double stretch(const Instance& p) {
    const glm::dmat3 m(float_matrix(p.object_to_world)), w(float_matrix(p.world_to_object));
    double most = 1.0;
    for (int r = 0; r < 3; ++r) {
        double row = 0.0;
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) row += std::abs(m[k][r]) * std::abs(w[c][k]);
        most = std::max(most, row);
    }
    return most;
}

// The placement's maps as the kernels hold them, in float.
Instance placement(const glm::dmat4& object_to_world) {
    Instance p{};
    store_rows(p.object_to_world, object_to_world);
    store_rows(p.world_to_object, glm::inverse(object_to_world));
    p.handedness = glm::determinant(glm::dmat3(object_to_world)) < 0.0 ? -1.0f : 1.0f;
    // The map's own rounding of the hit (the 2), and the way back, when a
    // ray leaving the point is mapped into the mesh's space again: its
    // rounding and the stored inverse's departure from the exact one, each
    // carried back to the world through the stretch (the 4 covers both, with
    // room). The identity's maps are exact: no rounding to cover.
    p.error_scale = object_to_world == glm::dmat4(1.0) ? 0.0f : float(2.0 + 4.0 * stretch(p));
    return p;
}

// The largest coordinate of a box, in magnitude.
float reach_of(const Bounds& b) {
    const glm::vec3 reach = glm::max(glm::abs(b.lo), glm::abs(b.hi));
    return std::max(std::max(reach.x, reach.y), reach.z);
}

// A placement's box grown for the rounding of a ray mapped into the mesh's
// space, which moves a hit by a few ulps (2^-22 and less) of the larger of its
// coordinates and the ray's origin, times the stretch: by 2^-18 of the box's
// reach and 2^-21 of the scene's, each times the stretch. An origin beyond
// the scene's reach adds ulps of its own, which the box test's own pad, 2^-20
// of the origin's reach, covers up to a stretch of about 5
// (geometry/bvh_traverse.h).
Bounds grown(const Bounds& b, double stretch, float scene_reach) {
    const float pad = float(stretch) * std::max(0x1p-18f * reach_of(b), 0x1p-21f * scene_reach);
    return Bounds{b.lo - pad, b.hi + pad};
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

// The tree of the scene's triangles [first, first + count), appended.
uint32_t append_tree(Bvh& into, const Scene& scene, size_t first, size_t count) {
    const std::vector<glm::vec3> corners(scene.positions.begin() + 3 * first,
                                         scene.positions.begin() + 3 * (first + count));
    return append_tree(into, build_bvh(corners), uint32_t(first));
}

} // namespace

Bvh build_scene_bvh(const Scene& scene) {
    if (scene.instances.empty()) return build_bvh(scene.positions);

    // The placements, the world-space triangles under the identity first if
    // there are any, with their boxes in the world.
    const bool world = scene.world_triangle_count() > 0;
    std::vector<Instance> placements;
    std::vector<Bounds> boxes;
    if (world) {
        placements.push_back(placement(glm::dmat4(1.0)));
        boxes.push_back(triangle_bounds(scene, 0, scene.world_triangle_count()));
    }
    const std::vector<Bounds> mesh_boxes = shared_mesh_bounds(scene);
    for (const MeshInstance& instance : scene.instances) {
        placements.push_back(placement(instance.object_to_world));
        boxes.push_back(transformed_bounds(mesh_boxes[instance.mesh], instance.object_to_world));
    }
    Bounds scene_box;
    for (const Bounds& box : boxes) scene_box.grow(box);
    for (size_t i = 0; i < boxes.size(); ++i) boxes[i] = grown(boxes[i], stretch(placements[i]), reach_of(scene_box));
    Bvh bvh = build_box_bvh(boxes);
    const std::vector<uint32_t> top_order = std::move(bvh.order);
    bvh.order.clear();
    // The deepest path goes through the top tree into the deepest mesh's,
    // less the mesh's node 0, which holds its box and is no level of its own.
    const int top_depth = bvh.depth - 1;
    bvh.depth = 0;
    for (const BvhNode& node : bvh.nodes) // traversal enters a top leaf's `first` alone
        for (uint32_t child : node.child)
            if ((child & WF_BVH_LEAF) && (child & ~WF_BVH_LEAF) >> WF_BVH_COUNT_SHIFT != 0u)
                throw std::logic_error("build_scene_bvh: a top leaf holds more than one placement");

    // Each tree once, after the top tree: the world's, then the meshes'.
    const uint32_t world_root = world ? append_tree(bvh, scene, 0, scene.world_triangle_count()) : 0u;
    std::vector<uint32_t> mesh_root;
    for (const SharedMesh& mesh : scene.shared_meshes) mesh_root.push_back(append_tree(bvh, scene, mesh.first, mesh.count));
    for (uint32_t i : top_order) {
        Instance p = placements[i];
        p.root = world && i == 0 ? world_root : mesh_root[scene.instances[i - (world ? 1 : 0)].mesh];
        bvh.instances.push_back(p);
    }
    bvh.depth += top_depth;
    return bvh;
}

} // namespace wf
