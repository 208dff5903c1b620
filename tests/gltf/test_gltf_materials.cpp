// test_gltf_materials.cpp — glTF materials and extensions as read into
// SceneMaterial: factors, defaults, the KHR_materials_* the renderer supports,
// and a warning, once, for what it does not.
#include "gltf/gltf_document.h"

namespace wf {
namespace {

TEST_F(GltfLoaderTest, EmissiveStrengthMultipliesTheFactor) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    doc.gltf["materials"] = {
        {{"name", "lamp"},
         {"emissiveFactor", {0.5, 0.25, 1.0}},
         {"doubleSided", true},
         {"pbrMetallicRoughness", {{"baseColorFactor", {1.5, -0.5, 0.3, 1.0}}}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}},
        {{"name", "dim"}, {"emissiveFactor", {0.5, 0.25, 1.0}}}};
    const int positions = doc.add_vec3(kTriangle);
    for (int material : {0, 1}) {
        json primitive = triangle_primitive(positions);
        primitive["material"] = material;
        doc.add_mesh_node("m" + std::to_string(material), primitive);
    }
    const Scene scene = load_gltf(doc.write(dir_ / "emissive.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_TRUE(scene.warnings.empty());
    EXPECT_EQ(scene.materials[0].name, "lamp");
    EXPECT_TRUE(scene.materials[0].double_sided);
    expect_near(scene.materials[0].emission, {2, 1, 4});
    expect_near(scene.materials[0].base_color, {1, 0, 0.3f}); // clamped to [0, 1]
    EXPECT_FALSE(scene.materials[1].double_sided);
    expect_near(scene.materials[1].emission, {0.5f, 0.25f, 1});
    EXPECT_EQ(scene.triangle_material, (std::vector<uint32_t>{0, 1}));
}

TEST_F(GltfLoaderTest, PrimitivesWithoutMaterialShareOneDefault) {
    GltfDocument doc;
    doc.gltf["materials"] = {
        {{"name", "red"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}}};
    const int positions = doc.add_vec3(kTriangle);
    json red = triangle_primitive(positions);
    red["material"] = 0;
    doc.add_mesh_node("a", triangle_primitive(positions));
    doc.add_mesh_node("b", red);
    doc.add_mesh_node("c", triangle_primitive(positions));
    const Scene scene = load_gltf(doc.write(dir_ / "default.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.materials.size(), 2u);
    expect_near(scene.materials[1].base_color, {1, 1, 1});
    expect_near(scene.materials[1].emission, {0, 0, 0});
    EXPECT_EQ(scene.triangle_material, (std::vector<uint32_t>{1, 0, 1}));
    EXPECT_EQ(scene.triangle_mesh, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(scene.mesh_names, (std::vector<std::string>{"a", "b", "c"}));
}

// Textures are test_texture.cpp's; KHR_texture_transform is now supported.
TEST_F(GltfLoaderTest, UnknownExtensionsWarnButLoad) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_anisotropy", "KHR_texture_transform"};
    doc.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}}};
    json primitive = triangle_primitive(doc.add_vec3(kTriangle));
    primitive["material"] = 0;
    doc.add_mesh_node("textured", primitive);
    const Scene scene = load_gltf(doc.write(dir_ / "textured.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "extensions not supported, ignored: KHR_materials_anisotropy");
}

// A supported extension's property the renderer does not read is named once,
// with the number of materials that set it; a white attenuationColor changes
// nothing and is not mentioned. KHR_lights_punctual is supported: required,
// it loads, and it draws no warning.
TEST_F(GltfLoaderTest, UnreadPropertiesWarnOnce) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_volume", "KHR_materials_transmission", "KHR_lights_punctual"};
    doc.gltf["extensionsRequired"] = {"KHR_lights_punctual"};
    doc.gltf["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 2}}}}}}};
    const json tinted = {{"KHR_materials_volume", {{"thicknessFactor", 1}, {"attenuationColor", {1, 0.5, 1}},
                                                   {"attenuationDistance", 2}}},
                         {"KHR_materials_transmission", {{"transmissionFactor", 1}}}};
    doc.gltf["materials"] = {{{"extensions", tinted}},
                             {{"extensions", {{"KHR_materials_volume", {{"attenuationColor", {1, 0.5, 1}}}}}}},
                             {{"extensions", {{"KHR_materials_volume", {{"attenuationColor", {1, 1, 1}}}}}}}};
    const int positions = doc.add_vec3(kTriangle);
    for (int m = 0; m < 3; ++m) {
        json primitive = triangle_primitive(positions);
        primitive["material"] = m;
        doc.add_mesh_node("mesh " + std::to_string(m), primitive);
    }
    doc.add_root({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    const Scene scene = load_gltf(doc.write(dir_ / "unread.gltf"));
    ASSERT_EQ(scene.punctual_lights.size(), 1u);
    EXPECT_EQ(scene.warnings, (std::vector<std::string>{
                                  "material properties not supported, ignored: "
                                  "KHR_materials_volume.attenuationColor (2 material(s)), "
                                  "KHR_materials_volume.attenuationDistance (1 material(s))"}));
}

// specularColorFactor, KHR_materials_volume's thickness (thin wall or solid)
// and COLOR_0 in floats and in normalized bytes are read, with no warning.
TEST_F(GltfLoaderTest, SpecularColourThinWallsAndVertexColoursAreRead) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_specular", "KHR_materials_transmission", "KHR_materials_volume"};
    const json transmits = {{"transmissionFactor", 1}};
    doc.gltf["materials"] = {
        {{"extensions",
          {{"KHR_materials_specular", {{"specularColorFactor", {2, 0.5, 1}}}}, {"KHR_materials_transmission", transmits}}}},
        {{"extensions",
          {{"KHR_materials_transmission", transmits}, {"KHR_materials_volume", {{"thicknessFactor", 0.5}}}}}},
        {{"extensions",
          {{"KHR_materials_transmission", transmits}, {"KHR_materials_volume", {{"thicknessFactor", 0}}}}}}};
    const int positions = doc.add_vec3(kTriangle);
    const int float_colors = doc.add_vec4({1, 0, 0, 1, 0, 1, 0, 0.5f, 0, 0, 1, 0});
    const int byte_colors = doc.add_normalized_vec3({255, 0, 0, 0, 255, 0, 0, 0, 51});
    for (int m = 0; m < 3; ++m) {
        json primitive = triangle_primitive(positions);
        primitive["material"] = m;
        if (m < 2) primitive["attributes"]["COLOR_0"] = m == 0 ? float_colors : byte_colors;
        doc.add_mesh_node("mesh " + std::to_string(m), primitive);
    }
    const Scene scene = load_gltf(doc.write(dir_ / "read.gltf"));
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    ASSERT_EQ(scene.materials.size(), 3u);
    expect_near(scene.materials[0].specular_color, {2.0f, 0.5f, 1.0f});
    EXPECT_TRUE(scene.materials[0].thin_walled);  // no KHR_materials_volume
    EXPECT_FALSE(scene.materials[1].thin_walled); // a thickness: a solid
    EXPECT_TRUE(scene.materials[2].thin_walled);  // thickness 0
    ASSERT_EQ(scene.colors.size(), 9u);
    EXPECT_EQ(scene.colors[1], glm::vec4(0, 1, 0, 0.5f));
    EXPECT_EQ(scene.colors[5], glm::vec4(0, 0, 0.2f, 1)); // 51 / 255, alpha 1 for VEC3
    EXPECT_EQ(scene.colors[8], glm::vec4(1.0f));          // no COLOR_0: white
    EXPECT_TRUE(scene.has_vertex_colors());
}

// KHR_materials_clearcoat's and KHR_materials_sheen's factors are read
// (absent: no coat, no sheen); the coat's normal texture is not, and says so.
TEST_F(GltfLoaderTest, ClearcoatAndSheenAreReadAndTheCoatNormalMapWarned) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_materials_sheen"};
    doc.gltf["materials"] = {
        {{"extensions",
          {{"KHR_materials_clearcoat",
            {{"clearcoatFactor", 0.75}, {"clearcoatRoughnessFactor", 0.25}, {"clearcoatNormalTexture", {{"index", 0}}}}},
           {"KHR_materials_sheen", {{"sheenColorFactor", {1, 0.5, 0}}, {"sheenRoughnessFactor", 0.5}}}}}},
        json::object()};
    const int positions = doc.add_vec3(kTriangle);
    for (int m = 0; m < 2; ++m) {
        json primitive = triangle_primitive(positions);
        primitive["material"] = m;
        doc.add_mesh_node("mesh " + std::to_string(m), primitive);
    }
    const Scene scene = load_gltf(doc.write(dir_ / "coat.gltf"));
    EXPECT_FLOAT_EQ(scene.materials[0].clearcoat, 0.75f);
    EXPECT_FLOAT_EQ(scene.materials[0].clearcoat_roughness, 0.25f);
    EXPECT_FLOAT_EQ(scene.materials[1].clearcoat, 0.0f);
    expect_near(scene.materials[0].sheen_color, {1.0f, 0.5f, 0.0f});
    EXPECT_FLOAT_EQ(scene.materials[0].sheen_roughness, 0.5f);
    expect_near(scene.materials[1].sheen_color, {0.0f, 0.0f, 0.0f});
    EXPECT_EQ(scene.warnings, (std::vector<std::string>{"material properties not supported, ignored: "
                                                        "KHR_materials_clearcoat.clearcoatNormalTexture (1 material(s))"}));
}

TEST_F(GltfLoaderTest, VertexColoursOutsideZeroOneAreNamed) {
    GltfDocument doc;
    const int positions = doc.add_vec3(kTriangle);
    json primitive = triangle_primitive(positions);
    primitive["attributes"]["COLOR_0"] = doc.add_vec4({1, 0, 0, 1, 0, 2, 0, 1, 0, 0, 1, 1});
    doc.add_mesh_node("painted", primitive);
    try {
        load_gltf(doc.write(dir_ / "bright.gltf"));
        FAIL() << "a colour of 2 loaded";
    } catch (const InputError& e) {
        expect_mentions(e.what(), {"bright.gltf", "mesh 'painted'", "COLOR_0 element 1 is not in [0, 1]"});
    }
}

TEST_F(GltfLoaderTest, MetallicRoughnessTransmissionIorAndSpecularAreRead) {
    GltfDocument doc;
    doc.gltf["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_specular"};
    doc.gltf["materials"] = {
        {{"name", "gold"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {1.0, 0.71, 0.29, 1.0}}, {"metallicFactor", 1.0}, {"roughnessFactor", 0.25}}}},
        {{"name", "glass"},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}},
         {"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}, {"KHR_materials_ior", {{"ior", 1.33}}}}}},
        {{"name", "matte"},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 2.0}}},
         {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}}};
    const int positions = doc.add_vec3(kTriangle);
    for (int material : {0, 1, 2, -1}) {
        json primitive = triangle_primitive(positions);
        if (material >= 0) primitive["material"] = material;
        doc.add_mesh_node("m" + std::to_string(material + 1), primitive);
    }
    const Scene scene = load_gltf(doc.write(dir_ / "materials.gltf"));
    expect_well_formed(scene);
    EXPECT_TRUE(scene.warnings.empty());
    ASSERT_EQ(scene.materials.size(), 4u);
    const SceneMaterial &gold = scene.materials[0], &glass = scene.materials[1], &matte = scene.materials[2],
                        &fallback = scene.materials[3];
    expect_near(gold.base_color, {1.0f, 0.71f, 0.29f});
    EXPECT_FLOAT_EQ(gold.metallic, 1.0f);
    EXPECT_FLOAT_EQ(gold.roughness, 0.25f);
    EXPECT_FLOAT_EQ(gold.transmission, 0.0f);
    EXPECT_FLOAT_EQ(gold.ior, 1.5f);     // KHR_materials_ior's default
    EXPECT_FLOAT_EQ(gold.specular, 1.0f); // KHR_materials_specular's default
    EXPECT_FLOAT_EQ(glass.transmission, 1.0f);
    EXPECT_FLOAT_EQ(glass.ior, 1.33f);
    EXPECT_FLOAT_EQ(glass.roughness, 0.0f);
    EXPECT_FLOAT_EQ(matte.roughness, 1.0f); // clamped to [0, 1]
    EXPECT_FLOAT_EQ(matte.specular, 0.0f);
    // glTF 2.0's default material: white, metallic 1, roughness 1.
    expect_near(fallback.base_color, {1, 1, 1});
    EXPECT_FLOAT_EQ(fallback.metallic, 1.0f);
    EXPECT_FLOAT_EQ(fallback.roughness, 1.0f);
}

TEST_F(GltfLoaderTest, IorBelowOneIsNamed) {
    GltfDocument doc;
    doc.gltf["materials"] = {{{"name", "odd"}, {"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}}};
    json primitive = triangle_primitive(doc.add_vec3(kTriangle));
    primitive["material"] = 0;
    doc.add_mesh_node("m", primitive);
    expect_mentions(load_error(doc.write(dir_ / "ior.gltf")), {"ior.gltf", "material 'odd'", "ior 0.5"});
}

TEST_F(GltfLoaderTest, SkinsMorphTargetsAndAnimationsAreReportedOnce) {
    GltfDocument doc;
    const int positions = doc.add_vec3(kTriangle);
    json primitive = triangle_primitive(positions);
    primitive["targets"] = {{{"POSITION", positions}}, {{"POSITION", positions}}};
    doc.add_mesh_node("a", primitive);
    doc.add_mesh_node("b", primitive);
    doc.gltf["skins"] = {{{"joints", {0}}}};
    doc.gltf["animations"] = {{{"channels", json::array()}, {"samplers", json::array()}}};
    const Scene scene = load_gltf(doc.write(dir_ / "animated.gltf"));
    expect_well_formed(scene);
    ASSERT_EQ(scene.warnings.size(), 3u);
    expect_mentions(scene.warnings[0], {"1 skin", "bind pose"});
    expect_mentions(scene.warnings[1], {"morph targets", "2 primitive"});
    expect_mentions(scene.warnings[2], {"1 animation"});
}

} // namespace
} // namespace wf
