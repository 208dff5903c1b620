// test_gltf_textures.cpp — the glTF side of textures (gltf_textures.h): real
// assets load with their images, bad images fail naming image and material,
// samplers, alpha modes and KHR_texture_transform are read; and tangents
// (scene/tangents.h), generated where a normal-mapped file has none. The
// texture lookup itself is tests/kernels/test_texture.cpp's.
#include "gltf/gltf_document.h"

#include <OpenImageIO/imageio.h>

#include "device/device_scene.h"
#include "scene/tangents.h"
#include "support/test_support.h"

namespace wf {
namespace {

// ---------------------------------------------------------------------------
// glTF: real assets

double mean_red(const TextureSet& set, size_t info) {
    const TextureInfo& i = set.infos[info];
    double sum = 0;
    for (size_t k = 0; k < size_t(i.width) * i.height; ++k) sum += set.texels[i.offset + k] & 0xffu;
    return sum / (double(i.width) * i.height * 255.0);
}

TEST(TextureGltf, BoxTexturedLoadsItsPng) {
    const Scene scene = load_gltf(kRealScenes + "BoxTextured/BoxTextured.gltf");
    ASSERT_EQ(scene.textures.infos.size(), 1u);
    const TextureInfo& info = scene.textures.infos[0];
    EXPECT_EQ(info.width, 256u);
    EXPECT_EQ(info.height, 256u);
    EXPECT_EQ(info.channels, 3u);
    EXPECT_EQ(info.flags, WF_TEXTURE_SRGB);
    EXPECT_EQ(info.wrap_s, WF_WRAP_REPEAT);
    EXPECT_EQ(scene.materials[0].textures[WF_TEXTURE_BASE_COLOR].texture, 0);
    EXPECT_EQ(scene.materials[0].textures[WF_TEXTURE_NORMAL].texture, -1);
    const double mean = mean_red(scene.textures, 0);
    EXPECT_GT(mean, 0.1);
    EXPECT_LT(mean, 0.95);
    test::report_measured("BoxTextured: 256x256 base colour, mean red " + std::to_string(mean));
}

TEST(TextureGltf, DamagedHelmetLoadsFiveEmbeddedJpegs) {
    const Scene scene = load_gltf(kRealScenes + "DamagedHelmet/DamagedHelmet.glb");
    const SceneMaterial& m = scene.materials[0];
    for (uint32_t slot : {WF_TEXTURE_BASE_COLOR, WF_TEXTURE_METALLIC_ROUGHNESS, WF_TEXTURE_NORMAL, WF_TEXTURE_EMISSIVE})
        ASSERT_GE(m.textures[slot].texture, 0) << "slot " << slot;
    EXPECT_EQ(scene.textures.infos.size(), 4u); // occlusion is not read
    for (const TextureInfo& info : scene.textures.infos) {
        EXPECT_EQ(info.width, 2048u);
        EXPECT_EQ(info.height, 2048u);
    }
    EXPECT_EQ(scene.textures.infos[size_t(m.textures[WF_TEXTURE_BASE_COLOR].texture)].flags, WF_TEXTURE_SRGB);
    EXPECT_EQ(scene.textures.infos[size_t(m.textures[WF_TEXTURE_EMISSIVE].texture)].flags, WF_TEXTURE_SRGB);
    EXPECT_EQ(scene.textures.infos[size_t(m.textures[WF_TEXTURE_NORMAL].texture)].flags, 0u);
    const double base = mean_red(scene.textures, size_t(m.textures[WF_TEXTURE_BASE_COLOR].texture));
    const double normal = mean_red(scene.textures, size_t(m.textures[WF_TEXTURE_NORMAL].texture));
    EXPECT_GT(base, 0.05);
    EXPECT_LT(base, 0.9);
    EXPECT_NEAR(normal, 0.5, 0.1); // tangent-space x centred on 0
    std::vector<uint32_t> order(scene.triangle_count());
    std::iota(order.begin(), order.end(), 0u);
    DeviceSceneData data;
    add_texture_data(scene, order, data);
    EXPECT_EQ(data.texcoords.size(), scene.triangle_count());
    EXPECT_EQ(data.texture_refs.size(), scene.materials.size() * WF_TEXTURE_SLOTS);
    test::report_measured("DamagedHelmet: 4 textures of 2048x2048 in " + std::to_string(data.bytes()) +
                          " bytes (RGBA8), base colour mean red " + std::to_string(base));
}

TEST(TextureGltf, TransmissionTestReadsAlphaMask) {
    const Scene scene = load_gltf(kRealScenes + "TransmissionTest/TransmissionTest.gltf");
    size_t masked = 0;
    for (const SceneMaterial& m : scene.materials) masked += m.alpha_mode == WF_ALPHA_MASK;
    EXPECT_EQ(masked, 6u);
}

TEST(TextureGltf, ToyCarReadsTextureTransform) {
    const Scene scene = load_gltf(kRealScenes + "ToyCar/ToyCar.gltf");
    bool transformed = false;
    for (const SceneMaterial& m : scene.materials)
        for (const TextureRef& ref : m.textures)
            transformed = transformed || (ref.texture >= 0 && (ref.transform[0] != 1.0f || ref.transform[2] != 0.0f ||
                                                              ref.transform[4] != 1.0f || ref.transform[5] != 0.0f));
    EXPECT_TRUE(transformed);
}

// ---------------------------------------------------------------------------
// glTF: files written here

class TextureGltfFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("wf_texture_test_" + std::to_string(getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    void write_png(const std::string& name, int width, int height, int channels, const std::vector<unsigned char>& pixels) {
        auto out = OIIO::ImageOutput::create((dir_ / name).string());
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:UnassociatedAlpha", 1); // the pixels given are straight alpha
        ASSERT_TRUE(out->open((dir_ / name).string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
        out->close();
    }

    // One triangle with `material`; `images` and `textures` as given.
    std::string write_gltf(const json& material, const json& images, const json& textures,
                           const json& extra = json::object()) {
        const std::vector<float> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        std::string blob(reinterpret_cast<const char*>(xyz.data()), xyz.size() * 4);
        std::ofstream(dir_ / "tri.bin", std::ios::binary) << blob;
        json doc = {{"asset", {{"version", "2.0"}}},
                    {"buffers", {{{"uri", "tri.bin"}, {"byteLength", 36}}}},
                    {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
                    {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                                    {"min", {0, 0, 0}}, {"max", {1, 1, 0}}}}},
                    {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 0}}}}}}},
                    {"nodes", {{{"mesh", 0}}}},
                    {"scenes", {{{"nodes", {0}}}}},
                    {"scene", 0},
                    {"materials", {material}},
                    {"images", images},
                    {"textures", textures}};
        doc.update(extra);
        const fs::path path = dir_ / "textured.gltf";
        std::ofstream(path) << doc.dump(1);
        return path.string();
    }

    fs::path dir_;
};

const json kBaseColorMaterial = {{"name", "Painted"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}};

TEST_F(TextureGltfFiles, MissingImageNamesFileImageAndMaterial) {
    const std::string path = write_gltf(kBaseColorMaterial, {{{"uri", "nowhere.png"}}}, {{{"source", 0}}});
    expect_mentions(load_error(path), {"textured.gltf", "material 'Painted'", "baseColorTexture", "image 0 'nowhere.png'",
                                       "no such file"});
}

TEST_F(TextureGltfFiles, CorruptPngNamesImageAndMaterial) {
    std::ofstream(dir_ / "broken.png", std::ios::binary) << "\x89PNG\r\n\x1a\n but nothing after the signature";
    const json material = {{"name", "Glowing"}, {"emissiveTexture", {{"index", 0}}}};
    const std::string path = write_gltf(material, {{{"uri", "broken.png"}}}, {{{"source", 0}}});
    expect_mentions(load_error(path), {"textured.gltf", "material 'Glowing'", "emissiveTexture", "image 0 'broken.png'",
                                       "cannot decode"});
}

TEST_F(TextureGltfFiles, PngTexelsSamplerAndAlphaAreRead) {
    // 2x1 grey+alpha: straight alpha must survive (OpenImageIO would premultiply by default).
    write_png("ga.png", 2, 1, 2, {200, 128, 10, 255});
    const json material = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}},
                                                     {"baseColorFactor", {1, 1, 1, 0.5}}}},
                           {"normalTexture", {{"index", 0}, {"scale", 0.25}}},
                           {"alphaMode", "MASK"}, {"alphaCutoff", 0.3}};
    const json extra = {{"samplers", {{{"magFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33648}}}}};
    const Scene scene = load_gltf(write_gltf(material, {{{"uri", "ga.png"}}}, {{{"source", 0}, {"sampler", 0}}}, extra));
    ASSERT_EQ(scene.textures.infos.size(), 2u);    // one image, two colour spaces
    EXPECT_EQ(scene.textures.texels.size(), 2u);    // decoded once
    EXPECT_EQ(scene.textures.texels[0], pack_rgba8(200, 200, 200, 128));
    EXPECT_EQ(scene.textures.texels[1], pack_rgba8(10, 10, 10, 255));
    const SceneMaterial& m = scene.materials[0];
    const TextureInfo& base = scene.textures.infos[size_t(m.textures[WF_TEXTURE_BASE_COLOR].texture)];
    EXPECT_EQ(base.flags, WF_TEXTURE_SRGB | WF_TEXTURE_NEAREST);
    EXPECT_EQ(base.wrap_s, WF_WRAP_CLAMP_TO_EDGE);
    EXPECT_EQ(base.wrap_t, WF_WRAP_MIRRORED_REPEAT);
    EXPECT_EQ(base.channels, 2u);
    EXPECT_EQ(m.textures[WF_TEXTURE_BASE_COLOR].texcoord, 1u);
    EXPECT_EQ(scene.textures.infos[size_t(m.textures[WF_TEXTURE_NORMAL].texture)].flags, WF_TEXTURE_NEAREST);
    EXPECT_FLOAT_EQ(m.normal_scale, 0.25f);
    EXPECT_EQ(m.alpha_mode, WF_ALPHA_MASK);
    EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.3f);
    EXPECT_FLOAT_EQ(m.base_alpha, 0.5f);
}

TEST_F(TextureGltfFiles, DataUriGreyImageAndTransformAndBlend) {
    write_png("one.png", 1, 1, 1, {7}); // grey, as ToyCar's L8 image
    std::ifstream in(dir_ / "one.png", std::ios::binary);
    const std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64;
    for (size_t at = 0; at < png.size(); at += 3) {
        uint32_t group = 0;
        for (size_t k = 0; k < 3; ++k) group = group << 8 | (at + k < png.size() ? uint8_t(png[at + k]) : 0u);
        const size_t present = std::min<size_t>(3, png.size() - at);
        for (size_t k = 0; k < 4; ++k) b64 += k <= present ? digits[group >> (18 - 6 * k) & 63u] : '=';
    }
    const json transform = {{"offset", {0.5, 0.25}}, {"rotation", 0.0}, {"scale", {2, 4}}, {"texCoord", 1}};
    const json material = {{"pbrMetallicRoughness",
                            {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}},
                           {"alphaMode", "BLEND"}};
    const json extra = {{"extensionsUsed", {"KHR_texture_transform"}}};
    const Scene scene =
        load_gltf(write_gltf(material, {{{"uri", "data:image/png;base64," + b64}}}, {{{"source", 0}}}, extra));
    ASSERT_EQ(scene.textures.texels.size(), 1u);
    EXPECT_EQ(scene.textures.texels[0], pack_rgba8(7, 7, 7, 255));
    EXPECT_EQ(scene.textures.infos[0].channels, 1u);
    const TextureRef& ref = scene.materials[0].textures[WF_TEXTURE_BASE_COLOR];
    EXPECT_EQ(ref.texcoord, 1u);
    const float expected[6] = {2, 0, 0.5f, 0, 4, 0.25f};
    for (int i = 0; i < 6; ++i) EXPECT_FLOAT_EQ(ref.transform[i], expected[i]) << i;
    EXPECT_EQ(scene.materials[0].alpha_mode, WF_ALPHA_MASK);
    EXPECT_FLOAT_EQ(scene.materials[0].alpha_cutoff, 0.5f);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "alpha mode BLEND on 1 material(s) is rendered as MASK with cutoff 0.5");
}

// Textures inside material extensions (tinygltf leaves them as JSON):
// specular and transmission linear, specular colour sRGB, each with its own
// texCoord and KHR_texture_transform; a malformed one is named.
TEST_F(TextureGltfFiles, ExtensionTexturesFillTheirSlots) {
    write_png("rgba.png", 1, 1, 4, {10, 20, 30, 40});
    const json transform = {{"KHR_texture_transform", {{"offset", {0.5, 0}}}}};
    const json material = {
        {"extensions",
         {{"KHR_materials_specular",
           {{"specularTexture", {{"index", 0}, {"texCoord", 1}}},
            {"specularColorTexture", {{"index", 0}, {"extensions", transform}}}}},
          {"KHR_materials_transmission", {{"transmissionFactor", 1}, {"transmissionTexture", {{"index", 0}}}}}}}};
    const json extra = {{"extensionsUsed", {"KHR_materials_specular", "KHR_materials_transmission",
                                             "KHR_texture_transform"}}};
    const Scene scene = load_gltf(write_gltf(material, {{{"uri", "rgba.png"}}}, {{{"source", 0}}}, extra));
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    const SceneMaterial& m = scene.materials[0];
    const auto flags = [&](uint32_t slot) { return scene.textures.infos[size_t(m.textures[slot].texture)].flags; };
    EXPECT_EQ(flags(WF_TEXTURE_SPECULAR), 0u);
    EXPECT_EQ(flags(WF_TEXTURE_SPECULAR_COLOR), WF_TEXTURE_SRGB);
    EXPECT_EQ(flags(WF_TEXTURE_TRANSMISSION), 0u);
    EXPECT_EQ(m.textures[WF_TEXTURE_SPECULAR].texcoord, 1u);
    EXPECT_FLOAT_EQ(m.textures[WF_TEXTURE_SPECULAR_COLOR].transform[2], 0.5f);
    EXPECT_LT(m.textures[WF_TEXTURE_BASE_COLOR].texture, 0);

    const json broken = {{"extensions", {{"KHR_materials_specular", {{"specularTexture", {{"texCoord", 0}}}}}}}};
    expect_mentions(load_error(write_gltf(broken, {{{"uri", "rgba.png"}}}, {{{"source", 0}}})),
                    {"textured.gltf", "KHR_materials_specular.specularTexture", "integer index"});
}

// ---------------------------------------------------------------------------
// Tangents (host/scene/tangents.h, and the loader's use of them)

TEST(TextureTangents, QuadWithKnownUvsGivesTangentAndHandedness) {
    const std::vector<glm::vec3> p = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    const std::vector<glm::vec3> n(4, glm::vec3(0, 0, 1));
    const std::vector<uint32_t> corners = {0, 1, 2, 0, 2, 3};
    // u along +x, v along +y: tangent +x, bitangent +y = cross(+z, +x), so w = +1.
    for (const glm::vec4& t : generate_tangents(p, n, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, corners)) {
        EXPECT_NEAR(glm::distance(glm::vec3(t), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
        EXPECT_EQ(t.w, 1.0f);
    }
    // u mirrored: tangent -x, bitangent still +y = -cross(+z, -x), so w = -1.
    for (const glm::vec4& t : generate_tangents(p, n, {{1, 0}, {0, 0}, {0, 1}, {1, 1}}, corners)) {
        EXPECT_NEAR(glm::distance(glm::vec3(t), glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);
        EXPECT_EQ(t.w, -1.0f);
    }
    // Normals tilted off +z: the tangent is made orthogonal to each, still unit.
    const glm::vec3 tilted = glm::normalize(glm::vec3(1, 0, 1));
    for (const glm::vec4& t : generate_tangents(p, std::vector<glm::vec3>(4, tilted), {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, corners)) {
        EXPECT_NEAR(glm::dot(glm::vec3(t), tilted), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-6f);
        EXPECT_GT(t.x, 0.0f);
    }
}

TEST(TextureTangents, DegenerateUvsGiveAnyOrthogonalTangentNeverNaN) {
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
    const std::vector<glm::vec3> n = {{0, 0, 1}, {0, 0, -1}, glm::normalize(glm::vec3(1, 2, 3)), {0, 0, 0}};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const std::vector<glm::vec2>& uv : {std::vector<glm::vec2>(4, glm::vec2(0.5f)),
                                             std::vector<glm::vec2>{{0, 0}, {1, 1}, {2, 2}, {3, 3}},
                                             std::vector<glm::vec2>(4, glm::vec2(nan))}) {
        const std::vector<glm::vec4> t = generate_tangents(p, n, uv, {0, 1, 2, 3, 3, 3});
        for (size_t i = 0; i < 3; ++i) {
            EXPECT_NEAR(glm::length(glm::vec3(t[i])), 1.0f, 1e-5f) << i;
            EXPECT_NEAR(glm::dot(glm::vec3(t[i]), n[i]), 0.0f, 1e-5f) << i;
            EXPECT_EQ(std::abs(t[i].w), 1.0f);
        }
        EXPECT_TRUE(std::isfinite(t[3].x) && std::isfinite(t[3].y) && std::isfinite(t[3].z)); // zero normal, zero area
    }
}

TEST(TextureTangents, NormalTangentTestLoadsWithFiniteUnitTangents) {
    const Scene scene = load_gltf(kRealScenes + "NormalTangentTest/NormalTangentTest.gltf");
    ASSERT_EQ(scene.tangents.size(), scene.positions.size());
    ASSERT_EQ(scene.uv0.size(), scene.positions.size());
    double worst_length = 0, worst_dot = 0;
    glm::dvec2 uv_lo(1e9), uv_hi(-1e9);
    for (size_t i = 0; i < scene.tangents.size(); ++i) {
        const glm::vec4& t = scene.tangents[i];
        ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) << i;
        ASSERT_EQ(std::abs(t.w), 1.0f) << i;
        worst_length = std::max(worst_length, double(std::abs(glm::length(glm::vec3(t)) - 1.0f)));
        worst_dot = std::max(worst_dot, double(std::abs(glm::dot(glm::vec3(t), scene.normals[i]))));
        uv_lo = glm::min(uv_lo, glm::dvec2(scene.uv0[i]));
        uv_hi = glm::max(uv_hi, glm::dvec2(scene.uv0[i]));
    }
    EXPECT_LT(worst_length, 1e-5);
    EXPECT_LT(worst_dot, 1e-5);
    EXPECT_GT(uv_hi.x - uv_lo.x, 0.5); // the UVs were read, not zero
    test::report_measured("NormalTangentTest: " + std::to_string(scene.tangents.size()) +
                          " generated tangents, largest | |t| - 1 | " + std::to_string(worst_length) +
                          ", largest |t . n| " + std::to_string(worst_dot));
}

} // namespace
} // namespace wf
