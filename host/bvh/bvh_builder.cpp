// bvh_builder.cpp — collapses the binary BVH into 8-wide nodes: of every way
// to do so, the one of least SAH cost (the dynamic programme of Ylitie et al.,
// "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs",
// HPG 2017). SAH chose the binary splits; the collapse chooses which binary
// nodes become wide nodes, which leaves, and which give their two children
// to their parent's slots. Its costs count four-triangle tests, as the binary
// builder's do: a node visit kNodeCost (bvh_builder.h), a leaf one test for
// every four of its triangles (leaf_tests), each times its box's area. Per
// binary node, bottom up, the least cost of its subtree in at most i slots
// of a node, for i = 1 to 8: in one, as a leaf (of at most max_run
// triangles, kMaxLeafRun) or as a node of its own; in more, its two children
// sharing them in the cheapest way. A node's children are then its subtree
// in eight slots. Against opening the largest child first (Embree's wide
// builders, and this file's until 2026-12-06), it meets 8-10% fewer triangle
// blocks a ray on ToyCar and MetalRoughSpheres for as many nodes; over a
// binary tree built down to single triangles, whose leaves it then makes,
// 11-13% fewer there and 18% fewer on the Cornell box
// (bench/results/ray-throughput.md).
//
// Slots. A node's children sit in slots of decreasing area: an any-hit query
// goes on to the last slot it meets and back down (kernels/geometry/
// bvh_traverse.h), so it meets the smaller boxes first, which measured faster
// for shadow rays than the order of the binary tree. Node 0 is a node of one
// slot, the scene's box: traversal reads that box and starts at its child,
// the top of the tree. Each node's subtree follows it, its interior
// children's in slot order: a GPU's traversal finds a path again from node
// indices alone (rebuild_stack, kernels/geometry/bvh_traverse.h).
//
// The stack bound. A visit that meets k >= 2 children pushes k - 1 and goes
// on to the other, so a subtree needs room for k - 1 more than the child it
// goes on to (counted below as k at once: one to spare). A binary subtree of
// height h (a leaf has 0) needs h + 1 left as it is. Each node is given a
// budget, the room left to its subtree: the whole stack at the root, which
// kMaxBinaryDepth keeps at least the root's height + 1. Where the cheapest
// children would leave one that becomes a node a budget below its own height
// + 1 (the children's budget being the node's, less k - 1), the node opens
// instead the largest child first while every one keeps that budget; so every
// subtree fits its budget, and traversal never overflows its stack. It
// binds rarely: at 139 of ToyCar's nodes (where long thin triangles make a
// deep binary tree), at none of MetalRoughSpheres', FlightHelmet's or a
// generated 4.2 M-triangle scene's.
#include "bvh/bvh_builder.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

#include "bvh/binary_bvh.h"
#include "bvh/leaf_blocks.h"
#include "geometry/bvh_traverse.h"

namespace wf {
namespace {

static_assert(kMaxBinaryDepth <= WF_BVH_STACK_SIZE, "the root's budget must cover its height + 1");

class Collapser {
public:
    // max_run: the most triangles (or boxes) a leaf of the wide tree may hold.
    Collapser(BinaryBvh binary, uint32_t max_run)
        : binary_(std::move(binary)), max_run_(max_run), first_(binary_.nodes.size()),
          triangles_(binary_.nodes.size()), height_(binary_.nodes.size(), 0), as_leaf_(binary_.nodes.size(), false),
          choices_(binary_.nodes.size()) {
        price(0);
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
    // The least costs of binary node n's subtree in at most i slots of a wide
    // node, cost[i] for i = 1 to 8 (SAH times its area), and how (choices_):
    // in one slot, as a leaf or a node of its own (as_leaf_); in more, with
    // fewer, or its left child taking left_slots[i] and its right the rest.
    // Recursive, so that only the path being priced holds costs (the
    // binary tree's depth is bounded: kMaxBinaryDepth).
    using Costs = std::array<double, WF_BVH_WIDTH + 1>;
    struct Choices {
        std::array<uint8_t, WF_BVH_WIDTH + 1> left_slots{};
        uint16_t fewer = 0; // bit i: at most i slots cost what at most i - 1 do
    };

    Costs price(uint32_t n) {
        const BinaryBvhNode& node = binary_.nodes[n];
        const double area = half_area(node.bounds);
        Costs cost{};
        if (node.count > 0) {
            first_[n] = node.first;
            triangles_[n] = node.count;
            cost.fill(area * leaf_tests(node.count, kMaxLeafSize));
            return cost;
        }
        const uint32_t left = node.first, right = node.first + 1;
        const Costs left_cost = price(left), right_cost = price(right);
        first_[n] = first_[left]; // a subtree's triangles are consecutive
        triangles_[n] = triangles_[left] + triangles_[right];
        height_[n] = 1 + std::max(height_[left], height_[right]);
        Choices& c = choices_[n];
        Costs split{}; // split[i]: the cheapest share of i slots between the two children
        for (int i = 2; i <= WF_BVH_WIDTH; ++i) {
            split[i] = std::numeric_limits<double>::infinity();
            for (int k = 1; k < i; ++k)
                if (left_cost[k] + right_cost[i - k] < split[i]) {
                    split[i] = left_cost[k] + right_cost[i - k];
                    c.left_slots[i] = static_cast<uint8_t>(k);
                }
        }
        const double as_node = kNodeCost * area + split[WF_BVH_WIDTH];
        const double as_leaf = area * leaf_tests(triangles_[n], kMaxLeafSize);
        as_leaf_[n] = triangles_[n] <= max_run_ && as_leaf <= as_node;
        cost[1] = as_leaf_[n] ? as_leaf : as_node;
        for (int i = 2; i <= WF_BVH_WIDTH; ++i) {
            const bool fewer = !(split[i] < cost[i - 1]);
            c.fewer |= static_cast<uint16_t>(fewer ? 1u << i : 0u);
            cost[i] = fewer ? cost[i - 1] : split[i];
        }
        return cost;
    }

    bool interior(uint32_t n) const { return binary_.nodes[n].count == 0; }
    // Whether binary node n, in a slot of its own, becomes a wide node.
    bool node_in_slot(uint32_t n) const { return interior(n) && !as_leaf_[n]; }

    // Whether children `kids` fit a node of this budget (see above).
    bool fits(const std::vector<uint32_t>& kids, int budget) const {
        const int k = static_cast<int>(kids.size());
        int highest = -1; // the greatest height + 1 among the children that become nodes
        for (uint32_t c : kids)
            if (node_in_slot(c)) highest = std::max(highest, height_[c] + 1);
        return k <= budget && highest <= budget - (k - 1);
    }

    // The subtrees that binary node `n`, taking at most `slots` slots, puts in them.
    void pieces(uint32_t n, int slots, std::vector<uint32_t>& kids) const {
        while (slots > 1 && interior(n) && (choices_[n].fewer >> slots & 1u)) --slots;
        if (slots == 1 || !interior(n)) {
            kids.push_back(n);
            return;
        }
        const int left = choices_[n].left_slots[slots];
        pieces(binary_.nodes[n].first, left, kids);
        pieces(binary_.nodes[n].first + 1, slots - left, kids);
    }

    // Children in slots of decreasing area, so that an any-hit query, which
    // goes on to the last slot met and then back down (bvh_traverse.h),
    // meets the smaller boxes first.
    std::vector<uint32_t> by_area(std::vector<uint32_t> kids) const {
        std::stable_sort(kids.begin(), kids.end(), [&](uint32_t a, uint32_t b) {
            return half_area(binary_.nodes[a].bounds) > half_area(binary_.nodes[b].bounds);
        });
        return kids;
    }

    // The children of the wide node made from interior binary node `n`: the
    // cheapest share of its eight slots, or, where that would not fit the
    // stack's budget, the largest boxes opened first while they fit.
    std::vector<uint32_t> open(uint32_t n, int budget) const {
        std::vector<uint32_t> kids;
        const int left = choices_[n].left_slots[WF_BVH_WIDTH];
        pieces(binary_.nodes[n].first, left, kids);
        pieces(binary_.nodes[n].first + 1, WF_BVH_WIDTH - left, kids);
        if (fits(kids, budget)) return by_area(kids);
        kids = {binary_.nodes[n].first, binary_.nodes[n].first + 1};
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
        return by_area(kids);
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

    // Per binary node: its subtree's triangles, its height, whether in one
    // slot it is a leaf rather than a node, and how it shares slots.
    BinaryBvh binary_;
    uint32_t max_run_;
    std::vector<uint32_t> first_, triangles_;
    std::vector<int> height_;
    std::vector<bool> as_leaf_;
    std::vector<Choices> choices_;
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
