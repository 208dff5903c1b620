// test_gltf_float_range.cpp — numbers that pass every check as doubles but
// are Inf as the renderer's floats, in the file or once multiplied out. They
// rendered black with exit 0 (issue 15); each must fail with one line naming
// the thing at fault and the value.
#include "gltf/gltf_document.h"

namespace wf {
namespace {

GltfDocument one_triangle(json node = json::object()) {
    GltfDocument doc;
    doc.add_mesh_node("triangle", triangle_primitive(doc.add_vec3(kTriangle)), node);
    return doc;
}

// An emissive material 'lamp' on the triangle.
GltfDocument emissive(const json& factor, double strength) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    doc.gltf["materials"] = {{{"name", "lamp"},
                              {"emissiveFactor", factor},
                              {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", strength}}}}}}};
    json primitive = triangle_primitive(doc.add_vec3(kTriangle));
    primitive["material"] = 0;
    doc.add_mesh_node("triangle", primitive);
    return doc;
}

TEST_F(GltfLoaderTest, EmissionPastFloatIsNamed) {
    expect_mentions(load_error(emissive({1, 1, 1}, 1e39).write(dir_ / "strength.gltf")),
                    {"strength.gltf: material 'lamp': emissiveFactor x emissiveStrength is 1e+39, not finite as a float"});
    // Each a float, the product not.
    expect_mentions(load_error(emissive({0, 2, 0}, 2e38).write(dir_ / "product.gltf")),
                    {"product.gltf: material 'lamp': emissiveFactor x emissiveStrength is 4e+38"});
    EXPECT_EQ(load_gltf(emissive({0, 1, 0}, 2e38).write(dir_ / "fits.gltf")).materials[0].emission.y, 2e38f);
}

TEST_F(GltfLoaderTest, WorldTransformPastFloatIsNamed) {
    GltfDocument doc;
    doc.gltf["meshes"].push_back({{"name", "triangle"}, {"primitives", {triangle_primitive(doc.add_vec3(kTriangle))}}});
    const int child = doc.add_node({{"name", "child"}, {"mesh", 0}, {"scale", {1e30, 1, 1}}});
    doc.add_root({{"name", "parent"}, {"scale", {1e30, 1, 1}}, {"children", {child}}});
    expect_mentions(load_error(doc.write(dir_ / "scale.gltf")),
                    {"scale.gltf: node 'child': world transform entry [0][0] is 1e+60, not finite as a float"});
    expect_mentions(load_error(one_triangle({{"translation", {0, 1e39, 0}}}).write(dir_ / "translation.gltf")),
                    {"translation.gltf: node 0: world transform entry [1][3] is 1e+39, not finite as a float"});
}

// Each corner and the transform are floats; their sum is not.
TEST_F(GltfLoaderTest, VertexPastFloatAfterTheNodeTransformIsNamed) {
    GltfDocument doc;
    doc.add_mesh_node("far", triangle_primitive(doc.add_vec3({3e38f, 0, 0, 3e38f, 1, 0, 3e38f, 0, 1})),
                      {{"translation", {3e38, 0, 0}}});
    expect_mentions(load_error(doc.write(dir_ / "vertex.gltf")),
                    {"vertex.gltf: node 0: mesh 'far': vertex 0 leaves float range"});
}

TEST_F(GltfLoaderTest, LightIntensityPastFloatIsNamed) {
    GltfDocument doc = one_triangle();
    doc.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
    doc.gltf["extensions"] = {
        {"KHR_lights_punctual", {{"lights", {{{"name", "sun"}, {"type", "directional"}, {"intensity", 1e39}}}}}}};
    doc.add_root({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    expect_mentions(load_error(doc.write(dir_ / "light.gltf")),
                    {"light.gltf: node 1: light 0 'sun': color x intensity is 1e+39, not finite as a float"});
}

TEST_F(GltfLoaderTest, CameraAspectPastFloatIsNamed) {
    GltfDocument doc = one_triangle();
    doc.gltf["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"aspectRatio", 1e39}, {"znear", 0.1}}}}};
    doc.add_root({{"camera", 0}});
    expect_mentions(load_error(doc.write(dir_ / "camera.gltf")),
                    {"camera.gltf: camera 0: aspectRatio is 1e+39, not finite as a float"});
}

TEST_F(GltfLoaderTest, MaterialNumbersPastFloatAreNamed) {
    GltfDocument doc = one_triangle();
    doc.gltf["materials"] = {{{"name", "cut"}, {"alphaMode", "MASK"}, {"alphaCutoff", 1e39}}};
    doc.gltf["meshes"][0]["primitives"][0]["material"] = 0;
    expect_mentions(load_error(doc.write(dir_ / "cutoff.gltf")),
                    {"cutoff.gltf: material 'cut': alphaCutoff is 1e+39, not finite as a float"});
    doc.gltf["materials"] = {
        {{"name", "shiny"}, {"extensions", {{"KHR_materials_specular", {{"specularColorFactor", {1, 1e39, 1}}}}}}}};
    expect_mentions(load_error(doc.write(dir_ / "specular.gltf")),
                    {"specular.gltf: material 'shiny': KHR_materials_specular.specularColorFactor is 1e+39"});
}

} // namespace
} // namespace wf
