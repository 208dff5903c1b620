// test_bvh.cpp — the BVH builder keeps its promises on random and degenerate
// input, and traversal answers exactly what brute force over every triangle
// answers with the same triangle test and the same rule for choosing among
// hits: the same triangle, the same t to the bit, the same any-hit verdict.
// Over 400 lines on purpose: every test runs the one brute-force harness and
// the tree walk that checks the builder, both defined here.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "bvh/binary_bvh.h"
#include "bvh/bvh_builder.h"
#include "support/closed_meshes.h"
#include "geometry/bvh_traverse.h"

namespace wf {
namespace {

using wf_device::RayHit;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;
    float t_max = kInfinity;
};

uint32_t bits(float f) {
    uint32_t b;
    std::memcpy(&b, &f, 4);
    return b;
}

// A scene's triangles with their BVH, in blocks of four in BVH order as the
// device reads them (lanes no leaf uses repeat lane 0, as
// host/device/device_scene.cpp fills them). Every fifth triangle of the input
// is an emitter, so that comparisons also cover the rule that prefers
// emitters (bvh_traverse.h).
struct BvhScene {
    explicit BvhScene(std::vector<glm::vec3> corners)
        : positions(std::move(corners)), bvh(build_bvh(positions)) {
        // Rounded up, so that a BVH breaking the promise of whole blocks fails
        // TreeCheck's assertion rather than this loop.
        triangles.resize((bvh.order.size() + WF_BLOCK_LANES - 1) / WF_BLOCK_LANES);
        for (size_t i = 0; i < bvh.order.size(); ++i) {
            TriangleBlock& block = triangles[i / WF_BLOCK_LANES];
            const size_t lane = i % WF_BLOCK_LANES;
            const size_t t = stand_in(i);
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 3; ++k) block.corners[3 * c + k][lane] = positions[3 * t + c][k];
            block.material[lane] = 0;
            block.light[lane] = triangle_at(i) >= 0 && t % 5 == 0 ? 0 : -1;
        }
    }
    // The scene triangle at BVH position i, or -1 for a lane no leaf uses.
    // The triangle whose corners lane i holds: its own, else its block's lane
    // 0 (else triangle 0, where a broken tree leaves even that empty).
    size_t stand_in(size_t i) const {
        const size_t lane0 = i - i % WF_BLOCK_LANES;
        return triangle_at(i) >= 0 ? bvh.order[i] : (triangle_at(lane0) >= 0 ? bvh.order[lane0] : 0);
    }
    int64_t triangle_at(size_t i) const {
        return i >= bvh.order.size() || bvh.order[i] == kNoTriangle ? -1 : int64_t{bvh.order[i]};
    }
    RayHit closest(const Ray& r) const {
        return wf_device::bvh_closest_hit(bvh.nodes.data(), triangles.data(), r.origin, r.direction, r.t_max);
    }
    bool any(const Ray& r, float t_max) const {
        return wf_device::bvh_any_hit(bvh.nodes.data(), triangles.data(), r.origin, r.direction, t_max) != 0;
    }
    // The BVH positions of the triangles the ray hits with no limit on t, in
    // index order: those it hits below any t_max are among them. Four at a
    // time, in the lanes of the same test (each lane's answer is
    // intersect_triangle's), for speed; corners gathered here from the input.
    std::vector<int32_t> hit_triangles(const Ray& r) const {
        const wf_device::WatertightRay w = wf_device::watertight_ray(r.origin, r.direction);
        std::vector<int32_t> hit;
        for (size_t first = 0; first < bvh.order.size(); first += WF_BLOCK_LANES) {
            float lanes[3][3][4]; // corner, permuted axis, lane
            uint32_t real = 0;
            for (size_t lane = 0; lane < 4; ++lane) {
                real |= (triangle_at(first + lane) >= 0 ? 1u : 0u) << lane;
                const size_t t = stand_in(first + lane);
                for (int c = 0; c < 3; ++c)
                    for (int k = 0; k < 3; ++k)
                        lanes[c][k][lane] = positions[3 * t + c][k == 0 ? w.kx : (k == 1 ? w.ky : w.kz)];
            }
            wf_device::TriangleLanes four;
            wf_device::CornerLanes* corner_lanes[3] = {&four.v0, &four.v1, &four.v2};
            for (int c = 0; c < 3; ++c) {
                corner_lanes[c]->x = wf_device::vload4(0, lanes[c][0]);
                corner_lanes[c]->y = wf_device::vload4(0, lanes[c][1]);
                corner_lanes[c]->z = wf_device::vload4(0, lanes[c][2]);
            }
            wf_device::TriangleHit h[4];
            const uint32_t found = wf_device::intersect_triangles(&w, &four, real, kInfinity, kInfinity, h);
            for (size_t lane = 0; lane < 4; ++lane)
                if (found >> lane & 1u) hit.push_back(static_cast<int32_t>(first + lane));
        }
        return hit;
    }
    // Brute force: every triangle of `candidates` tested below t_max, and the
    // hits passed to traversal's own selection rule in index order.
    RayHit select(const Ray& r, const std::vector<int32_t>& candidates, float t_max) const {
        const wf_device::WatertightRay w = wf_device::watertight_ray(r.origin, r.direction);
        wf_device::HitSelection selection = wf_device::no_hits(t_max);
        for (int32_t i : candidates) {
            wf_device::TriangleHit h;
            if (hits(w, static_cast<size_t>(i), t_max, &h))
                wf_device::select_hit(&selection, &h, i, -1, light(static_cast<size_t>(i)) >= 0);
        }
        return wf_device::selected_hit(&selection);
    }
    RayHit brute_force(const Ray& r) const { return select(r, hit_triangles(r), r.t_max); }
    int32_t light(size_t i) const { return wf_device::triangle_light(triangles.data(), static_cast<uint32_t>(i)); }

    std::vector<glm::vec3> positions;
    Bvh bvh;
    std::vector<TriangleBlock> triangles;

private:
    bool hits(const wf_device::WatertightRay& w, size_t i, float t_max, wf_device::TriangleHit* hit) const {
        const glm::vec3* p = &positions[3 * bvh.order[i]];
        return wf_device::intersect_triangle(&w, p[0], p[1], p[2], t_max, hit) != 0;
    }
};

// Slot `slot`'s box in a node.
struct Box {
    glm::vec3 lo, hi;
};

Box slot_box(const BvhNode& node, int slot) {
    Box b;
    for (int k = 0; k < 3; ++k) {
        b.lo[k] = node.bounds[2 * k][slot];
        b.hi[k] = node.bounds[2 * k + 1][slot];
    }
    return b;
}

bool inside(const Box& box, const glm::vec3& p) {
    for (int k = 0; k < 3; ++k)
        if (!(box.lo[k] <= p[k] && p[k] <= box.hi[k])) return false;
    return true;
}

bool inside(const Box& outer, const Box& inner) { return inside(outer, inner.lo) && inside(outer, inner.hi); }

// The promises of bvh_builder.h, checked by walking the tree from the root.
class TreeCheck {
public:
    explicit TreeCheck(const BvhScene& scene)
        : scene_(scene), in_leaves_(scene.bvh.order.size(), 0), visits_(scene.bvh.nodes.size(), 0) {}

    void run() {
        const Bvh& bvh = scene_.bvh;
        const size_t count = scene_.positions.size() / 3;
        ASSERT_EQ(bvh.order.size() % WF_BLOCK_LANES, 0u);
        ASSERT_GE(bvh.order.size(), count);
        std::vector<int> in_order(count, 0);
        for (uint32_t t : bvh.order) {
            if (t == kNoTriangle) continue;
            ASSERT_LT(t, count);
            ++in_order[t];
        }
        const int need = walk(0, 1, nullptr);
        for (size_t t = 0; t < count; ++t) EXPECT_EQ(in_order[t], 1) << "triangle " << t << " in order";
        for (size_t i = 0; i < bvh.order.size(); ++i)
            EXPECT_EQ(in_leaves_[i], scene_.triangle_at(i) >= 0 ? 1 : 0) << "BVH position " << i << " in leaves";

        for (size_t n = 0; n < visits_.size(); ++n) EXPECT_EQ(visits_[n], 1) << "node " << n;
        EXPECT_EQ(depth_, bvh.depth);
        EXPECT_LE(need, WF_BVH_STACK_SIZE) << "traversal could overflow its stack";
    }

private:
    // The stack room that traversal below this node may need when every box
    // is met: k pushed at once, k - 1 more than the child it goes on to.
    int walk(uint32_t index, int level, const Box* parent) {
        depth_ = std::max(depth_, level);
        ++visits_[index];
        const BvhNode& node = scene_.bvh.nodes[index];
        int used = 0, deepest = 0;
        double last_area = std::numeric_limits<double>::infinity();
        for (int slot = 0; slot < WF_BVH_WIDTH; ++slot) {
            const Box box = slot_box(node, slot);
            if (box.lo.x == kInfinity) { // unused: an empty box, which no ray meets, and no child
                for (int k = 0; k < 3; ++k) EXPECT_TRUE(box.lo[k] == kInfinity && box.hi[k] == -kInfinity);
                EXPECT_EQ(node.child[slot], 0u) << "node " << index << " slot " << slot;
                continue;
            }
            ++used;
            if (parent) EXPECT_TRUE(inside(*parent, box)) << "node " << index << " slot " << slot << " outside";
            const double area = half_area(Bounds{box.lo, box.hi});
            EXPECT_LE(area, last_area) << "node " << index << " slot " << slot << ": slots by decreasing area";
            last_area = area;
            const uint32_t child = node.child[slot];
            if (child & WF_BVH_LEAF) {
                const uint32_t first = child & WF_BVH_FIRST_MASK;
                const uint32_t count = ((child & ~WF_BVH_LEAF) >> WF_BVH_COUNT_SHIFT) + 1;
                EXPECT_LE(size_t{first} + count, in_leaves_.size());
                if (count >= WF_BLOCK_LANES)
                    EXPECT_EQ(first % WF_BLOCK_LANES, 0u) << "a leaf of four or more starts a block";
                else
                    EXPECT_EQ(first / WF_BLOCK_LANES, (first + count - 1) / WF_BLOCK_LANES) << "within one block";
                for (uint32_t i = first; i < first + count && i < in_leaves_.size(); ++i) {
                    ++in_leaves_[i];
                    for (int c = 0; c < 3; ++c)
                        EXPECT_TRUE(inside(box, scene_.positions[3 * size_t{scene_.bvh.order[i]} + c]))
                            << "node " << index << " slot " << slot;
                }
                continue;
            }
            // Children come after their parent, so the walk cannot cycle.
            EXPECT_GT(child, index);
            EXPECT_LT(child, scene_.bvh.nodes.size());
            if (child <= index || child >= scene_.bvh.nodes.size()) continue;
            deepest = std::max(deepest, walk(child, level + 1, &box));
        }
        EXPECT_GT(used, 0) << "node " << index;
        if (index == 0) EXPECT_EQ(used, 1) << "node 0 holds the scene's box alone";
        return used == 1 ? deepest : std::max(used, used - 1 + deepest);
    }

    const BvhScene& scene_;
    std::vector<int> in_leaves_, visits_;
    int depth_ = 0;
};

void expect_valid(const BvhScene& scene) { TreeCheck(scene).run(); }

// Closest hits and any-hit verdicts against brute force; returns the number of
// rays that hit something.
int expect_agreement(const BvhScene& scene, const std::vector<Ray>& rays) {
    int failures = 0, hits = 0;
    auto fail = [&failures](size_t ray, const char* what) {
        if (++failures <= 10) ADD_FAILURE() << "ray " << ray << ": " << what;
    };
    for (size_t i = 0; i < rays.size(); ++i) {
        const std::vector<int32_t> candidates = scene.hit_triangles(rays[i]);
        const RayHit expected = scene.select(rays[i], candidates, rays[i].t_max);
        const RayHit got = scene.closest(rays[i]);
        if (got.triangle != expected.triangle)
            fail(i, "closest hit: another triangle");
        else if (expected.triangle >= 0 && (bits(got.t) != bits(expected.t) || bits(got.u) != bits(expected.u) ||
                                            bits(got.v) != bits(expected.v)))
            fail(i, "closest hit: another t, u or v");
        hits += expected.triangle >= 0;

        // Any-hit limits below, at, just above and beyond the hit chosen with no limit.
        const RayHit all = scene.select(rays[i], candidates, kInfinity);
        const float t = all.t;
        const float limits[] = {all.triangle >= 0 ? 0.5f * t : 1.0f, t, std::nextafter(t, kInfinity),
                                2.0f * t};
        for (float limit : limits)
            if (scene.any(rays[i], limit) != (scene.select(rays[i], candidates, limit).triangle >= 0))
                fail(i, "any hit");

        // Two rays traced in turn (kernels/geometry/trace_width.h): the same answers as each alone.
        if (i == 0) continue;
        const glm::vec3 origin[2] = {rays[i - 1].origin, rays[i].origin};
        const glm::vec3 direction[2] = {rays[i - 1].direction, rays[i].direction};
        for (const float limit : {kInfinity, t}) {
            for (int stop_at_first_hit = 0; stop_at_first_hit < 2; ++stop_at_first_hit) {
                RayHit pair[2];
                wf_device::bvh_traverse_pair(scene.bvh.nodes.data(), scene.triangles.data(), origin, direction, limit,
                                             stop_at_first_hit, nullptr, pair);
                for (int k = 0; k < 2; ++k) {
                    const RayHit alone = wf_device::bvh_traverse(scene.bvh.nodes.data(), scene.triangles.data(),
                                                                 origin[k], direction[k], limit, stop_at_first_hit);
                    if (pair[k].triangle != alone.triangle || bits(pair[k].t) != bits(alone.t) ||
                        bits(pair[k].u) != bits(alone.u) || bits(pair[k].v) != bits(alone.v))
                        fail(i, "two rays in turn");
                }
            }
        }
    }
    EXPECT_EQ(failures, 0);
    return hits;
}

// Seeded draws: uniform numbers in [lo, hi), points in a cube, unit vectors.
struct Random {
    explicit Random(uint32_t seed) : rng(seed) {}
    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    glm::vec3 point(float lo, float hi) {
        return glm::vec3(uniform(lo, hi), uniform(lo, hi), uniform(lo, hi));
    }
    glm::vec3 unit() {
        std::normal_distribution<float> n;
        return glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
    }
    std::mt19937 rng;
};

void add_triangle(std::vector<glm::vec3>& p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    p.push_back(a);
    p.push_back(b);
    p.push_back(c);
}

// Exactly degenerate: coincident corners, or corners that differ in x only.
void add_zero_area(Random& r, std::vector<glm::vec3>& p) {
    const glm::vec3 a = r.point(-10.0f, 10.0f);
    switch (r.integer(0, 2)) {
    case 0: add_triangle(p, a, a, r.point(-10.0f, 10.0f)); break;
    case 1: add_triangle(p, a, a, a); break;
    default:
        add_triangle(p, a, a + glm::vec3(r.uniform(-5.0f, 5.0f), 0, 0),
                     a + glm::vec3(r.uniform(-5.0f, 5.0f), 0, 0));
    }
}

// A soup in [-10, 10]^3 of every kind of triangle traversal meets.
std::vector<glm::vec3> random_soup(Random& r, int count) {
    std::vector<glm::vec3> p;
    for (int i = 0; i < count; ++i) {
        const int kind = i % 10;
        if (kind < 5) { // ordinary, sizes from 0.01 to 3
            const glm::vec3 c = r.point(-10.0f, 10.0f);
            const float size = std::pow(10.0f, r.uniform(-2.0f, 0.5f));
            add_triangle(p, c + size * r.unit(), c + size * r.unit(), c + size * r.unit());
        } else if (kind < 7) { // long and thin
            const glm::vec3 a = r.point(-10.0f, 10.0f);
            const glm::vec3 b = a + r.uniform(3.0f, 15.0f) * r.unit();
            const float width = std::pow(10.0f, r.uniform(-4.0f, -2.0f));
            add_triangle(p, a, b, a + r.uniform(0.0f, 1.0f) * (b - a) + width * r.unit());
        } else if (kind == 7) { // in an axis plane at a whole coordinate, shared by many
            const int axis = r.integer(0, 2);
            const float plane = static_cast<float>(r.integer(-10, 10));
            glm::vec3 c[3];
            const glm::vec3 center = r.point(-10.0f, 10.0f);
            for (glm::vec3& v : c) {
                v = center + r.uniform(0.1f, 2.0f) * r.unit();
                v[axis] = plane;
            }
            add_triangle(p, c[0], c[1], c[2]);
        } else if (kind == 8) {
            add_zero_area(r, p);
        } else { // an exact copy of an earlier triangle, or a neighbour across one of its edges
            const size_t t = 3 * static_cast<size_t>(r.integer(0, i - 1));
            const glm::vec3 a = p[t], b = p[t + 1], c = p[t + 2];
            if (r.integer(0, 1) == 0)
                add_triangle(p, a, b, c);
            else
                add_triangle(p, b, a, a + b - c);
        }
    }
    return p;
}

// Rays from inside and outside the soup: random, axis-aligned, with a zero
// component at a coordinate where boxes have planes, and aimed at corners and
// edge midpoints; a third of them with a finite t_max.
std::vector<Ray> random_rays(Random& r, const std::vector<glm::vec3>& p, int count) {
    std::vector<Ray> rays;
    auto some_corner = [&]() { return p[static_cast<size_t>(r.integer(0, static_cast<int>(p.size()) - 1))]; };
    for (int i = 0; i < count; ++i) {
        const int kind = i % 10;
        Ray ray;
        ray.origin = r.point(-10.0f, 10.0f);
        const float scale = r.uniform(0.1f, 10.0f); // directions need not be unit
        if (kind < 4) {
            ray.direction = scale * r.unit();
        } else if (kind < 6) { // from outside, towards the soup
            ray.origin = r.point(-30.0f, 30.0f);
            ray.direction = r.point(-10.0f, 10.0f) - ray.origin;
        } else if (kind == 6) { // along an axis, often exactly through a corner
            const int axis = r.integer(0, 2);
            ray.direction = glm::vec3(0.0f);
            ray.direction[axis] = r.integer(0, 1) ? scale : -scale;
            if (r.integer(0, 1)) {
                const glm::vec3 c = some_corner();
                for (int k = 0; k < 3; ++k)
                    if (k != axis) ray.origin[k] = c[k];
            }
        } else if (kind == 7) { // in a plane that boxes and axis-plane triangles share
            const int axis = r.integer(0, 2);
            ray.direction = scale * r.unit();
            ray.direction[axis] = 0.0f;
            ray.origin[axis] = r.integer(0, 1) ? some_corner()[axis] : static_cast<float>(r.integer(-10, 10));
        } else if (kind == 8) {
            ray.direction = some_corner() - ray.origin;
        } else {
            ray.direction = 0.5f * (some_corner() + some_corner()) - ray.origin;
        }
        if (i % 3 == 0) ray.t_max = r.uniform(0.0f, 30.0f) / glm::length(ray.direction);
        rays.push_back(ray);
    }
    return rays;
}

TEST(Bvh, RandomSoupAgreesWithBruteForce) {
    Random r(1);
    const BvhScene scene(random_soup(r, 10000));
    expect_valid(scene);
    const int hits = expect_agreement(scene, random_rays(r, scene.positions, 100000));
    EXPECT_GT(hits, 30000); // the comparison is about hits, not only misses
}

TEST(Bvh, RayAlongABoxFaceEntersTheBox) {
    // A ray running exactly in a face plane of a box, as an axis-aligned ray
    // from a point on an axis-aligned floor does, is inside the closed box,
    // whichever sign its zero component has.
    // The box fills slot 3 of a node whose other slots are unused but for
    // slot 0, the scene's box for box_ray, which is the same box.
    BvhNode node{};
    for (int slot = 0; slot < WF_BVH_WIDTH; ++slot)
        for (int k = 0; k < 3; ++k) {
            node.bounds[2 * k][slot] = slot == 0 || slot == 3 ? 0.0f : kInfinity;
            node.bounds[2 * k + 1][slot] = slot == 0 || slot == 3 ? 1.0f : -kInfinity;
        }
    for (float y : {0.0f, 1.0f}) {
        for (float zero : {0.0f, -0.0f}) {
            const glm::vec3 origin(0.5f, y, -1.0f);
            const wf_device::BoxRay ray = wf_device::box_ray(&node, origin, glm::vec3(0.0f, zero, 1.0f));
            float entry[WF_BVH_WIDTH];
            EXPECT_EQ(wf_device::child_entries(&ray, &node, kInfinity, entry), 1u | 1u << 3) << "y = " << y;
            EXPECT_NEAR(entry[3], 1.0f, 1e-5f) << "y = " << y;
        }
    }
}

TEST(Bvh, RejectsEmptyAndMalformedInput) {
    EXPECT_THROW(build_bvh({}), std::invalid_argument);
    EXPECT_THROW(build_bvh({glm::vec3(0.0f), glm::vec3(1.0f)}), std::invalid_argument);
    EXPECT_THROW(build_bvh({glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(kInfinity, 0.0f, 0.0f)}),
                 std::invalid_argument);
}

TEST(Bvh, OneTriangle) {
    const BvhScene scene({glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)});
    expect_valid(scene);
    EXPECT_EQ(scene.bvh.nodes.size(), 1u);
    EXPECT_EQ(scene.bvh.depth, 1);
    const RayHit hit = scene.closest(Ray{glm::vec3(0.25f, 0.25f, 1.0f), glm::vec3(0, 0, -2)});
    EXPECT_EQ(hit.triangle, 0);
    EXPECT_EQ(hit.t, 0.5f);
    EXPECT_EQ(hit.u, 0.25f);
    EXPECT_EQ(hit.v, 0.25f);
}

TEST(Bvh, IdenticalTrianglesSplitInHalf) {
    std::vector<glm::vec3> p;
    for (int i = 0; i < 10000; ++i)
        add_triangle(p, glm::vec3(-1, -1, 3), glm::vec3(2, 0, 3), glm::vec3(0, 2, 3.5f));
    const BvhScene scene(p);
    expect_valid(scene);
    EXPECT_EQ(build_binary_bvh(p).depth, 13); // 10000 halved 12 times reaches leaves of at most 4
    // Every copy is hit at the same t: of the emitters among them, the lowest index wins.
    const Ray ray{glm::vec3(0.1f, 0.2f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)};
    const RayHit hit = scene.closest(ray);
    int32_t first_emitter = 0;
    while (scene.light(static_cast<size_t>(first_emitter)) < 0) ++first_emitter;
    EXPECT_EQ(hit.triangle, first_emitter);
    EXPECT_EQ(bits(hit.t), bits(scene.brute_force(ray).t));
    Random r(2);
    expect_agreement(scene, random_rays(r, p, 2000));
}

TEST(Bvh, AllZeroAreaTriangles) {
    Random r(3);
    std::vector<glm::vec3> p;
    for (int i = 0; i < 10000; ++i) add_zero_area(r, p);
    const BvhScene scene(p);
    expect_valid(scene);
    expect_agreement(scene, random_rays(r, p, 5000));
}

TEST(Bvh, CollinearTriangles) {
    // Every corner on one axis-parallel line: every box has zero area.
    std::vector<glm::vec3> line;
    for (int i = 0; i < 5000; ++i) {
        const float x = static_cast<float>(i);
        add_triangle(line, glm::vec3(x, 2, 3), glm::vec3(x + 0.5f, 2, 3), glm::vec3(x + 3.0f, 2, 3));
    }
    const BvhScene flat(line);
    expect_valid(flat);
    Random r(4);
    expect_agreement(flat, random_rays(r, line, 2000));

    // Proper triangles strung along a diagonal.
    std::vector<glm::vec3> string;
    for (int i = 0; i < 5000; ++i) {
        const glm::vec3 c = 0.01f * static_cast<float>(i) * glm::vec3(1, 1, 1);
        add_triangle(string, c, c + glm::vec3(0.02f, 0, 0), c + glm::vec3(0, 0, 0.02f));
    }
    const BvhScene diagonal(string);
    expect_valid(diagonal);
    std::vector<Ray> rays;
    for (int i = 0; i < 2000; ++i) // across the string, through its triangles
        rays.push_back(
            Ray{glm::vec3(r.uniform(0.0f, 50.0f), -1.0f, r.uniform(0.0f, 50.0f)), glm::vec3(0, 1, 0)});
    for (Ray& ray : rays) ray.origin.z = ray.origin.x + r.uniform(0.0f, 0.02f);
    EXPECT_GT(expect_agreement(diagonal, rays), 100);
}

TEST(Bvh, ExponentialSpacingStaysWithinTheStack) {
    // Each triangle sits 16.5 times farther out along x than the next, so all
    // but the outermost share SAH's first bin and every split peels off one
    // triangle: 66 levels, unless the builder turns to median splits in time.
    std::vector<glm::vec3> p;
    for (float x = 1e38f; x > 0.0f; x /= 16.5f)
        add_triangle(p, glm::vec3(x, 0, 0), glm::vec3(x, 1, 0), glm::vec3(x, 0, 1));
    ASSERT_GT(p.size() / 3, 66u);
    const BvhScene scene(p);
    expect_valid(scene);
    EXPECT_GT(build_binary_bvh(p).depth, 48) << "the input no longer drives SAH towards the depth limit";
    Random r(5);
    std::vector<Ray> rays;
    for (int i = 0; i < 2000; ++i) {
        const float x = p[3 * static_cast<size_t>(r.integer(0, static_cast<int>(p.size() / 3) - 1))].x;
        const glm::vec3 origin(x * r.uniform(0.3f, 3.0f), r.uniform(0.0f, 0.5f), r.uniform(0.0f, 0.5f));
        rays.push_back(
            Ray{origin, glm::vec3(r.integer(0, 1) ? x : -x, r.uniform(-0.1f, 0.1f), r.uniform(-0.1f, 0.1f))});
    }
    EXPECT_GT(expect_agreement(scene, rays), 100);
}

// Rays aimed exactly at the vertices and edges of closed meshes, from inside,
// are the most delicate for the box test (test_watertight.cpp checks that
// every one of them hits): a sample of them against brute force.
TEST(Bvh, RaysAtMeshCracksAgreeWithBruteForce) {
    const glm::vec3 center(1.0f, 2.0f, -0.5f);
    // The cube's centre lies on planes of many boxes; its rays to the face
    // centres run along axes, and to the middle lines of the faces in axis planes.
    const std::pair<test::Mesh, std::vector<glm::vec3>> cases[] = {
        {test::icosphere(5, 3.0f, center),
         {center, center + glm::vec3(0.7f, -1.1f, 0.3f), center + glm::vec3(0.0f, 0.0f, 2.9f)}},
        {test::subdivided_cube(40), {glm::vec3(0.0f), glm::vec3(0.3f, -0.6f, 0.85f)}}};
    for (const auto& [mesh, origins] : cases) {
        const BvhScene scene(mesh.corners());
        expect_valid(scene);
        const std::vector<test::CrackPoint> points = test::crack_points(mesh);
        for (const glm::vec3& origin : origins) {
            std::vector<Ray> rays;
            for (size_t i = 0; i < points.size(); i += 41) rays.push_back(Ray{origin, points[i].point - origin});
            EXPECT_EQ(expect_agreement(scene, rays), static_cast<int>(rays.size()));
        }
    }
}

} // namespace
} // namespace wf
