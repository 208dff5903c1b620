// test_gltf_nodes.cpp — the node hierarchy as a hostile file may shape it: a
// chain far deeper than the call stack, cycles, and nodes with two parents.
#include "gltf/gltf_document.h"

namespace wf {
namespace {

// A chain of `depth` nodes, each moving its children 1e-3 along x, with a
// triangle at the bottom.
GltfDocument chain(int depth) {
    GltfDocument doc;
    doc.gltf["meshes"].push_back({{"name", "leaf"}, {"primitives", {triangle_primitive(doc.add_vec3(kTriangle))}}});
    for (int i = 0; i < depth; ++i) {
        json node = {{"translation", {1e-3, 0, 0}}};
        if (i + 1 < depth) node["children"] = {i + 1};
        else node["mesh"] = 0;
        if (i == 0) doc.add_root(node);
        else doc.add_node(node);
    }
    return doc;
}

// Walked on the loader's own stack: recursion ran out of call stack at a few
// ten thousand levels (issue 15).
TEST_F(GltfLoaderTest, HundredThousandDeepChainLoads) {
    const Scene scene = load_gltf(chain(100000).write(dir_ / "deep.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.triangle_count(), 1u);
    // 1e5 steps of 1e-3, summed in double: 100 to within float's rounding of it.
    expect_near(scene.positions[0], {100, 0, 0}, 1e-4f);
    expect_near(scene.positions[1], {101, 0, 0}, 1e-4f);
    expect_near(scene.positions[2], {100, 1, 0}, 1e-4f);
}

TEST_F(GltfLoaderTest, NodeThatIsItsOwnAncestorIsNamed) {
    GltfDocument doc = chain(5);
    doc.gltf["nodes"][4]["children"] = {2};
    expect_mentions(load_error(doc.write(dir_ / "cycle.gltf")), {"cycle.gltf: node 2: ", "its own ancestor"});
    doc.gltf["nodes"][4]["children"] = {4};
    expect_mentions(load_error(doc.write(dir_ / "self.gltf")), {"self.gltf: node 4: ", "its own ancestor"});
}

// Each node listing its child twice would double the instances at every
// level: 2^60 triangles from 60 nodes.
TEST_F(GltfLoaderTest, NodeWithTwoParentsIsNamed) {
    GltfDocument doc = chain(60);
    for (int i = 0; i + 1 < 60; ++i) doc.gltf["nodes"][size_t(i)]["children"] = {i + 1, i + 1};
    expect_mentions(load_error(doc.write(dir_ / "doubling.gltf")),
                    {"doubling.gltf: node 59: ", "reached a second time", "one parent"});
}

} // namespace
} // namespace wf
