// binary_bvh.cpp — binned SAH construction (Wald, "On fast Construction of
// SAH-based Bounding Volume Hierarchies", 2007).
//
// Each node sorts its triangles' centroids into kBinCount bins per axis and
// takes the bin boundary of least SAH cost. Costs count tests of four
// triangles, as the float4 leaf test makes them: a leaf of one to four costs
// the same, so splits that leave children of multiples of four pay. The tree
// goes down to single triangles: the collapse into wide nodes
// (bvh_builder.cpp) makes the leaves, of up to eight triangles, choosing
// among all of this tree's subtrees by the same costs (stopping here at four,
// where SAH said a leaf paid, cost the Cornell box's bounce rays a fifth of
// their speed: bench/results/ray-throughput.md). Two triangles split without
// binning, one a side. Without a usable split (all centroids in one place, or
// a box of zero area, which SAH cannot rank), up to kMaxLeafSize triangles
// stay a leaf, and more are halved at the centroid median, by index when all
// centroids coincide. A split that would leave too few levels below it is
// also replaced by the median split, which halves the count and so always
// fits, or by a leaf where four triangles or fewer are left: depth stays
// within kMaxBinaryDepth.
#include "bvh/binary_bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "wavefront/scene_types.h"

namespace wf {
namespace {

// 16 bins find splits nearly as good as a full sweep at a fraction of its cost.
constexpr int kBinCount = 16;

struct PrimRef {
    Bounds bounds;
    glm::vec3 centroid;
    uint32_t triangle;
};

// Depth of the subtree that median splits build over n triangles, in leaves of at most max_leaf.
int median_levels(uint32_t n, uint32_t max_leaf) {
    int levels = 1;
    for (; n > max_leaf; n = (n + 1) / 2) ++levels;
    return levels;
}

// Which bin a centroid falls in along each axis of the node's centroid bounds.
class BinMap {
public:
    explicit BinMap(const Bounds& centroids) : lo_(centroids.lo) {
        const glm::vec3 extent = centroids.extent();
        for (int axis = 0; axis < 3; ++axis) {
            // An axis too thin to divide puts everything in bin 0: no split on it.
            const float scale = kBinCount / extent[axis];
            scale_[axis] = std::isfinite(scale) ? scale : 0.0f;
        }
    }
    int bin(const glm::vec3& centroid, int axis) const {
        const int b = static_cast<int>((centroid[axis] - lo_[axis]) * scale_[axis]);
        return std::min(b, kBinCount - 1);
    }

private:
    glm::vec3 lo_;
    glm::vec3 scale_;
};

struct SahSplit {
    int axis = -1; // -1 when no boundary has triangles on both sides
    int bin = 0;   // bins below it go left
    uint32_t left_count = 0;
    // The children's areas times their four-triangle tests as leaves: SAH's
    // cost of the split, less the node's own share, the same for every split.
    double cost = std::numeric_limits<double>::infinity();
};

class Builder {
public:
    Builder(std::vector<PrimRef> prims, uint32_t max_leaf) : prims_(std::move(prims)), max_leaf_(max_leaf) {}
    BinaryBvh build();

private:
    void build_node(uint32_t node, uint32_t begin, uint32_t end, int depth);
    // Reorders [begin, end) and returns where the second child starts, or end
    // for a leaf.
    uint32_t split(uint32_t begin, uint32_t end, const Bounds& bounds, const Bounds& centroids, int depth);
    SahSplit best_sah_split(uint32_t begin, uint32_t end, const BinMap& bin_map) const;
    uint32_t median_split(uint32_t begin, uint32_t end, const Bounds& centroids);

    std::vector<PrimRef> prims_;
    uint32_t max_leaf_; // primitives a leaf holds at most
    BinaryBvh bvh_;
};

// The triangles' boxes, checked.
std::vector<PrimRef> triangle_prims(const std::vector<glm::vec3>& positions) {
    if (positions.empty()) throw std::invalid_argument("build_bvh: no triangles");
    if (positions.size() % 3 != 0)
        throw std::invalid_argument("build_bvh: " + std::to_string(positions.size()) +
                                    " corners is not a whole number of triangles");
    const size_t count = positions.size() / 3;
    if (count > size_t{WF_BVH_FIRST_MASK} + 1)
        throw std::invalid_argument("build_bvh: " + std::to_string(count) +
                                    " triangles exceed what a leaf's child word can index");
    std::vector<PrimRef> prims(count);
    for (size_t t = 0; t < count; ++t) {
        Bounds b;
        for (int corner = 0; corner < 3; ++corner) {
            const glm::vec3& p = positions[3 * t + corner];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw std::invalid_argument("build_bvh: triangle " + std::to_string(t) +
                                            " has a corner that is not finite");
            b.grow(p);
        }
        prims[t] = PrimRef{b, b.center(), static_cast<uint32_t>(t)};
    }
    return prims;
}

BinaryBvh Builder::build() {
    const uint32_t count = static_cast<uint32_t>(prims_.size());
    bvh_.nodes.reserve(2 * size_t{count} - 1);
    bvh_.nodes.resize(1);
    build_node(0, 0, count, 1);
    bvh_.order.resize(count);
    for (uint32_t i = 0; i < count; ++i) bvh_.order[i] = prims_[i].triangle;
    return std::move(bvh_);
}

void Builder::build_node(uint32_t node, uint32_t begin, uint32_t end, int depth) {
    bvh_.depth = std::max(bvh_.depth, depth);
    Bounds bounds, centroids;
    for (uint32_t i = begin; i < end; ++i) {
        bounds.grow(prims_[i].bounds);
        centroids.grow(prims_[i].centroid);
    }
    bvh_.nodes[node].bounds = bounds;
    const uint32_t mid = split(begin, end, bounds, centroids, depth);
    if (mid == end) {
        bvh_.nodes[node].first = begin;
        bvh_.nodes[node].count = end - begin;
        return;
    }
    const uint32_t children = static_cast<uint32_t>(bvh_.nodes.size());
    bvh_.nodes.resize(children + 2);
    bvh_.nodes[node].first = children;
    bvh_.nodes[node].count = 0;
    build_node(children, begin, mid, depth + 1);
    build_node(children + 1, mid, end, depth + 1);
}

uint32_t Builder::split(uint32_t begin, uint32_t end, const Bounds& bounds, const Bounds& centroids,
                        int depth) {
    const uint32_t count = end - begin;
    const double area = half_area(bounds);
    if (count > 1 && area > 0.0) {
        if (count == 2 && centroids.lo != centroids.hi && depth < kMaxBinaryDepth)
            return begin + 1; // the one split there is
        const BinMap bin_map(centroids);
        const SahSplit sah = best_sah_split(begin, end, bin_map);
        if (sah.axis >= 0) {
            const uint32_t larger_child = std::max(sah.left_count, count - sah.left_count);
            if (depth + median_levels(larger_child, max_leaf_) <= kMaxBinaryDepth) {
                const auto first = prims_.begin() + begin;
                const auto middle = std::partition(first, prims_.begin() + end, [&](const PrimRef& p) {
                    return bin_map.bin(p.centroid, sah.axis) < sah.bin;
                });
                return begin + static_cast<uint32_t>(middle - first);
            }
        }
    }
    if (count <= max_leaf_) return end;
    return median_split(begin, end, centroids);
}

SahSplit Builder::best_sah_split(uint32_t begin, uint32_t end, const BinMap& bin_map) const {
    struct Bin {
        Bounds bounds;
        uint32_t count = 0;
    };
    std::array<std::array<Bin, kBinCount>, 3> binned{};
    for (uint32_t i = begin; i < end; ++i) {
        const PrimRef& p = prims_[i];
        for (int axis = 0; axis < 3; ++axis) {
            Bin& b = binned[axis][bin_map.bin(p.centroid, axis)];
            b.bounds.grow(p.bounds);
            ++b.count;
        }
    }
    SahSplit best;
    for (int axis = 0; axis < 3; ++axis) {
        const std::array<Bin, kBinCount>& row = binned[axis];
        // Area and count of everything at or above each boundary.
        std::array<double, kBinCount> right_area{};
        std::array<uint32_t, kBinCount> right_count{};
        Bounds right;
        uint32_t right_total = 0;
        for (int b = kBinCount - 1; b > 0; --b) {
            right.grow(row[b].bounds);
            right_total += row[b].count;
            right_area[b] = half_area(right);
            right_count[b] = right_total;
        }
        Bounds left;
        uint32_t left_total = 0;
        for (int b = 1; b < kBinCount; ++b) {
            left.grow(row[b - 1].bounds);
            left_total += row[b - 1].count;
            if (left_total == 0 || right_count[b] == 0) continue;
            const double cost = half_area(left) * leaf_tests(left_total, max_leaf_) +
                                right_area[b] * leaf_tests(right_count[b], max_leaf_);
            if (cost < best.cost) best = SahSplit{axis, b, left_total, cost};
        }
    }
    return best;
}

uint32_t Builder::median_split(uint32_t begin, uint32_t end, const Bounds& centroids) {
    const uint32_t mid = begin + (end - begin) / 2;
    const glm::vec3 extent = centroids.extent();
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    // Centroids all in one place: any half is as good as the other, keep the order.
    if (extent[axis] > 0.0f)
        std::nth_element(
            prims_.begin() + begin, prims_.begin() + mid, prims_.begin() + end,
            [axis](const PrimRef& a, const PrimRef& b) { return a.centroid[axis] < b.centroid[axis]; });
    return mid;
}

} // namespace

double leaf_tests(uint32_t n, uint32_t max_leaf) { return static_cast<double>((n + max_leaf - 1) / max_leaf); }

double half_area(const Bounds& b) {
    if (b.empty()) return 0.0;
    const glm::dvec3 e = glm::dvec3(b.extent());
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

BinaryBvh build_binary_bvh(const std::vector<glm::vec3>& positions) {
    return Builder(triangle_prims(positions), kMaxLeafSize).build();
}

BinaryBvh build_binary_bvh(const std::vector<Bounds>& boxes) {
    if (boxes.empty()) throw std::invalid_argument("build_bvh: no boxes");
    if (boxes.size() > size_t{WF_BVH_FIRST_MASK} + 1)
        throw std::invalid_argument("build_bvh: " + std::to_string(boxes.size()) +
                                    " boxes exceed what a leaf's child word can index");
    std::vector<PrimRef> prims(boxes.size());
    for (size_t i = 0; i < boxes.size(); ++i) {
        const Bounds& b = boxes[i];
        const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
        if (b.empty() || !finite(b.lo) || !finite(b.hi))
            throw std::invalid_argument("build_bvh: box " + std::to_string(i) + " is empty or not finite");
        prims[i] = PrimRef{b, b.center(), static_cast<uint32_t>(i)};
    }
    return Builder(std::move(prims), 1).build();
}

} // namespace wf
