// bvh_builder.cpp — collapses the binary BVH into 8-wide nodes, as Embree's
// wide builders do: a node starts from its binary node's two children and
// keeps replacing the interior child of largest area by that child's two
// children, until it has eight or none is left to open. SAH chose the binary
// splits; opening the largest box first keeps the ones a ray meets most.
//
// Node 0 is a node of one slot, the scene's box: traversal reads that box and
// starts at its child, the top of the tree. Each node's subtree follows it,
// its interior children's in slot order: a GPU's traversal finds a path again
// from node indices alone (rebuild_stack, kernels/geometry/bvh_traverse.h).
//
// Leaves. The binary builder prices an interior node at a fraction of a wide
// node's visit, which is what the collapse makes of most of them. But a child
// left unopened, when its node is full, becomes a node of its own, a whole
// visit; and at the bottom of the tree most of those would hold two leaves.
// So such a child of at most max_run triangles (kMaxLeafRun) is priced again, its root
// at kNodeCost, and becomes one leaf (tested four triangles at a time) where
// that is no dearer. Besides the time, it saves the memory of those nodes.
//
// The stack bound. A visit that meets k >= 2 children pushes k - 1 and goes
// on to the other, so a subtree needs room for k - 1 more than the child it
// goes on to (counted below as k at once: one to spare). A binary subtree of
// height h (a leaf has 0) needs h + 1 left as it is. Each node is given a
// budget, the room left to its subtree: the whole stack at the root, which
// kMaxBinaryDepth keeps at least the root's height + 1. A child is opened
// only while every interior child keeps a budget of at least its own height
// + 1 (the children's budget being the node's, less k - 1), so every subtree
// fits its budget, and traversal never overflows its stack. Trees of real
// scenes are far too shallow for the budget ever to stop an opening.
#include "bvh/bvh_builder.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "bvh/binary_bvh.h"
#include "bvh/leaf_blocks.h"
#include "geometry/bvh_traverse.h"

namespace wf {
namespace {

static_assert(kMaxBinaryDepth <= WF_BVH_STACK_SIZE, "the root's budget must cover its height + 1");

// The most triangles in one leaf: what its child word can count.
constexpr uint32_t kMaxLeafRun = (~WF_BVH_LEAF >> WF_BVH_COUNT_SHIFT) + 1;
// A node visit in units of one four-triangle test (the binary builder's units).
constexpr double kNodeCost = 1.0;

class Collapser {
public:
    // max_run: the most triangles (or boxes) a leaf of the wide tree may hold.
    Collapser(BinaryBvh binary, uint32_t max_run)
        : binary_(std::move(binary)), first_(binary_.nodes.size()), triangles_(binary_.nodes.size()),
          height_(binary_.nodes.size(), 0), as_leaf_(binary_.nodes.size(), false) {
        // Children come after their parents, so a reverse sweep sees them first.
        std::vector<double> cost(binary_.nodes.size()); // SAH cost times area, as the subtree would be alone
        for (size_t n = binary_.nodes.size(); n-- > 0;) {
            const BinaryBvhNode& node = binary_.nodes[n];
            const double area = half_area(node.bounds);
            if (node.count > 0) {
                first_[n] = node.first;
                triangles_[n] = node.count;
                cost[n] = area;
                continue;
            }
            const uint32_t left = node.first, right = node.first + 1;
            first_[n] = first_[left]; // a subtree's triangles are consecutive
            triangles_[n] = triangles_[left] + triangles_[right];
            height_[n] = 1 + std::max(height_[left], height_[right]);
            const double as_node = kNodeCost * area + cost[left] + cost[right];
            const double as_leaf = area * ((triangles_[n] + kMaxLeafSize - 1) / kMaxLeafSize);
            as_leaf_[n] = triangles_[n] <= max_run && as_leaf <= as_node;
            cost[n] = std::min(as_leaf, as_node);
        }
    }

    // Node 0 has one slot, the binary root: traversal starts below it and
    // never pushes it.
    Bvh build() {
        bvh_.nodes.emplace_back();
        fill(0, {0u}, WF_BVH_STACK_SIZE, 1);
        bvh_.order = std::move(binary_.order);
        return std::move(bvh_);
    }

private:
    bool interior(uint32_t n) const { return binary_.nodes[n].count == 0; }

    // Whether children `kids` fit a node of this budget (see above).
    bool fits(const std::vector<uint32_t>& kids, int budget) const {
        const int k = static_cast<int>(kids.size());
        int highest = -1; // the greatest height + 1 among interior children
        for (uint32_t c : kids)
            if (interior(c)) highest = std::max(highest, height_[c] + 1);
        return k <= budget && highest <= budget - (k - 1);
    }

    // The children of the wide node made from interior binary node `n`.
    std::vector<uint32_t> open(uint32_t n, int budget) const {
        std::vector<uint32_t> kids{binary_.nodes[n].first, binary_.nodes[n].first + 1};
        while (kids.size() < WF_BVH_WIDTH) {
            int best = -1;
            double best_area = -1.0;
            for (size_t i = 0; i < kids.size(); ++i) {
                if (!interior(kids[i])) continue;
                std::vector<uint32_t> opened = kids;
                opened[i] = binary_.nodes[kids[i]].first;
                opened.push_back(binary_.nodes[kids[i]].first + 1);
                const double area = half_area(binary_.nodes[kids[i]].bounds);
                if (area > best_area && fits(opened, budget)) {
                    best = static_cast<int>(i);
                    best_area = area;
                }
            }
            if (best < 0) break;
            const uint32_t opened = kids[static_cast<size_t>(best)];
            kids[static_cast<size_t>(best)] = binary_.nodes[opened].first;
            kids.push_back(binary_.nodes[opened].first + 1);
        }
        return kids;
    }

    // Writes wide node `node` with these binary children, and their subtrees after it.
    void fill(uint32_t node, const std::vector<uint32_t>& kids, int budget, int level) {
        bvh_.depth = std::max(bvh_.depth, level);
        const int child_budget = budget - (static_cast<int>(kids.size()) - 1);
        const float inf = std::numeric_limits<float>::infinity();
        for (int slot = 0; slot < WF_BVH_WIDTH; ++slot) {
            const bool used = slot < static_cast<int>(kids.size());
            const BinaryBvhNode* kid = used ? &binary_.nodes[kids[static_cast<size_t>(slot)]] : nullptr;
            for (int axis = 0; axis < 3; ++axis) {
                bvh_.nodes[node].bounds[2 * axis][slot] = used ? kid->bounds.lo[axis] : inf;
                bvh_.nodes[node].bounds[2 * axis + 1][slot] = used ? kid->bounds.hi[axis] : -inf;
            }
            bvh_.nodes[node].child[slot] = 0u;
            if (!used) continue;
            const uint32_t binary_index = kids[static_cast<size_t>(slot)];
            if (kid->count > 0 || as_leaf_[binary_index]) {
                bvh_.nodes[node].child[slot] = WF_BVH_LEAF | (triangles_[binary_index] - 1) << WF_BVH_COUNT_SHIFT |
                                               first_[binary_index];
                continue;
            }
            const uint32_t index = static_cast<uint32_t>(bvh_.nodes.size());
            bvh_.nodes[node].child[slot] = index;
            bvh_.nodes.emplace_back();
            fill(index, open(binary_index, child_budget), child_budget, level + 1);
        }
    }

    // Per binary node: its subtree's triangles, its height, and whether, left
    // unopened, it becomes a leaf rather than a node.
    BinaryBvh binary_;
    std::vector<uint32_t> first_, triangles_;
    std::vector<int> height_;
    std::vector<bool> as_leaf_;
    Bvh bvh_;
};

} // namespace

Bvh build_bvh(const std::vector<glm::vec3>& positions) {
    Bvh bvh = Collapser(build_binary_bvh(positions), kMaxLeafRun).build();
    place_leaves_in_blocks(bvh);
    return bvh;
}

Bvh build_box_bvh(const std::vector<Bounds>& boxes) { return Collapser(build_binary_bvh(boxes), 1).build(); }

} // namespace wf
