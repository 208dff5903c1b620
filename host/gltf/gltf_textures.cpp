// gltf_textures.cpp — glTF textureInfo objects into TextureRefs, images into
// the TextureSet, each image decoded on first use.
#include "gltf/gltf_textures.h"

#include <tiny_gltf.h>

#include <filesystem>

#include "base/errors.h"
#include "gltf/gltf_diagnostics.h"
#include "gltf/gltf_file.h"
#include "gltf/gltf_float.h"

namespace wf {
namespace {

// "image 2 'albedo.png'": the uri where there is one (not for data URIs,
// which tinygltf does not keep), else the name.
std::string image_label(const tinygltf::Image& image, size_t index) {
    std::string label = indexed_label("image", index, image.uri.empty() ? image.name : image.uri);
    if (image.bufferView >= 0) label += " (bufferView " + std::to_string(image.bufferView) + ")";
    return label;
}

uint32_t wrap_mode(int wrap, const std::string& where, const char* axis) {
    if (wrap == int(WF_WRAP_REPEAT) || wrap == int(WF_WRAP_CLAMP_TO_EDGE) || wrap == int(WF_WRAP_MIRRORED_REPEAT))
        return uint32_t(wrap);
    fail(where, std::string(axis) + " " + std::to_string(wrap) +
                    " is not a glTF wrap mode (10497, 33071 or 33648)");
}

float float_number(const tinygltf::Value& value, const std::string& where, const char* what) {
    if (!value.IsNumber()) fail(where, std::string(what) + " is not a number");
    return to_float(value.GetNumberAsDouble(), where, what);
}

// KHR_texture_transform's [u, v] pair `name`, or `fallback`.
void read_pair(const tinygltf::Value& transform, const char* name, float out[2], const std::string& where) {
    if (!transform.Has(name)) return;
    const tinygltf::Value& pair = transform.Get(name);
    if (!pair.IsArray() || pair.ArrayLen() != 2)
        fail(where, std::string("KHR_texture_transform ") + name + " must have 2 numbers");
    for (int i = 0; i < 2; ++i) out[i] = float_number(pair.Get(i), where, "KHR_texture_transform number");
}

} // namespace

bool keep_image_encoded(tinygltf::Image* image, int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
    image->image.assign(bytes, bytes + (size > 0 ? size : 0));
    image->as_is = true;
    return true;
}

GltfTextures::GltfTextures(const tinygltf::Model& model, const std::string& path, TextureSet& set)
    : model_(model), path_(path), set_(set), image_offsets_(model.images.size(), -1),
      infos_(model.textures.size(), std::vector<int32_t>(2, -1)) {}

std::vector<std::string> GltfTextures::warnings() const {
    std::vector<std::string> said;
    if (blend_materials_)
        said.push_back("alpha mode BLEND on " + std::to_string(blend_materials_) +
                       " material(s) is rendered as MASK with cutoff 0.5");
    if (occlusion_materials_)
        said.push_back("occlusion maps on " + std::to_string(occlusion_materials_) +
                       " material(s) are not used: the paths themselves find what is occluded");
    if (high_texcoords_)
        said.push_back(std::to_string(high_texcoords_) +
                       " texture reference(s) ask for TEXCOORD_2 or above; TEXCOORD_0 is read instead");
    return said;
}

// The TextureInfo for glTF texture `index` in a colour space, made on first use.
int32_t GltfTextures::texture_info(int index, bool srgb, const std::string& where) {
    if (index < 0 || size_t(index) >= model_.textures.size())
        fail(where, "texture " + std::to_string(index) + " does not exist");
    int32_t& made = infos_[size_t(index)][srgb ? 1 : 0];
    if (made >= 0) return made;
    const tinygltf::Texture& texture = model_.textures[size_t(index)];
    const std::string texture_where = where + ": " + indexed_label("texture", size_t(index), texture.name);
    if (texture.source < 0 || size_t(texture.source) >= model_.images.size())
        fail(texture_where, "image " + std::to_string(texture.source) + " does not exist");
    const auto image_index = size_t(texture.source);
    const tinygltf::Image& image = model_.images[image_index];
    const std::string image_where = where + ": " + image_label(image, image_index);

    TextureInfo info{};
    info.wrap_s = info.wrap_t = WF_WRAP_REPEAT;
    if (texture.sampler >= 0) {
        if (size_t(texture.sampler) >= model_.samplers.size())
            fail(texture_where, "sampler " + std::to_string(texture.sampler) + " does not exist");
        const tinygltf::Sampler& sampler = model_.samplers[size_t(texture.sampler)];
        const std::string sampler_where = where + ": sampler " + std::to_string(texture.sampler);
        info.wrap_s = wrap_mode(sampler.wrapS, sampler_where, "wrapS");
        info.wrap_t = wrap_mode(sampler.wrapT, sampler_where, "wrapT");
        if (sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) info.flags |= WF_TEXTURE_NEAREST;
    }
    if (srgb) info.flags |= WF_TEXTURE_SRGB;

    if (image_offsets_[image_index] < 0) {
        if (!image.as_is || image.image.empty()) {
            if (image.uri.empty()) fail(image_where, "no image data");
            const std::filesystem::path file =
                std::filesystem::path(path_).parent_path() / uri_decode(image.uri);
            std::error_code error;
            fail(image_where, std::string(std::filesystem::exists(file, error) ? "cannot read " : "no such file ") +
                                  file.string());
        }
        const DecodedImage decoded =
            decode_image(image.image.data(), image.image.size(), image.uri, image_where);
        image_offsets_[image_index] = set_.add_texels(decoded, image_where);
        decoded_sizes_.resize(model_.images.size());
        decoded_sizes_[image_index] = {decoded.width, decoded.height, decoded.channels};
    }
    const auto& size = decoded_sizes_[image_index];
    info.offset = uint32_t(image_offsets_[image_index]);
    info.width = size[0];
    info.height = size[1];
    info.channels = size[2];
    made = set_.add_info(info, image_label(image, image_index));
    return made;
}

TextureRef GltfTextures::reference(int index, int tex_coord, const tinygltf::Value* transform_object, bool srgb,
                                   const std::string& where) {
    TextureRef ref = no_texture();
    if (index < 0) return ref;
    ref.texture = texture_info(index, srgb, where);
    if (transform_object && transform_object->IsObject()) {
        const tinygltf::Value& transform = *transform_object;
        float offset[2] = {0, 0}, scale[2] = {1, 1};
        read_pair(transform, "offset", offset, where);
        read_pair(transform, "scale", scale, where);
        const float rotation =
            transform.Has("rotation")
                ? float_number(transform.Get("rotation"), where, "KHR_texture_transform rotation")
                : 0.0f;
        const std::array<float, 6> matrix = texture_transform(offset[0], offset[1], rotation, scale[0], scale[1]);
        std::copy(matrix.begin(), matrix.end(), ref.transform);
        if (transform.Has("texCoord") && transform.Get("texCoord").IsInt())
            tex_coord = transform.Get("texCoord").GetNumberAsInt();
    }
    if (tex_coord < 0) fail(where, "texCoord " + std::to_string(tex_coord) + " is negative");
    if (tex_coord > 1) ++high_texcoords_;
    ref.texcoord = tex_coord == 1 ? 1u : 0u;
    return ref;
}

TextureRef GltfTextures::extension_reference(const tinygltf::Material& material, const char* extension,
                                             const char* property, bool srgb, const std::string& where) {
    const auto found = material.extensions.find(extension);
    if (found == material.extensions.end() || !found->second.Has(property)) return no_texture();
    const std::string info_where = where + ": " + extension + "." + property;
    const tinygltf::Value& info = found->second.Get(property);
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt())
        fail(info_where, "is not a textureInfo with an integer index");
    const int tex_coord = info.Has("texCoord") && info.Get("texCoord").IsInt() ? info.Get("texCoord").GetNumberAsInt() : 0;
    const tinygltf::Value* transform = nullptr;
    if (info.Has("extensions") && info.Get("extensions").Has("KHR_texture_transform"))
        transform = &info.Get("extensions").Get("KHR_texture_transform");
    return reference(info.Get("index").GetNumberAsInt(), tex_coord, transform, srgb, info_where);
}

void GltfTextures::convert(const tinygltf::Material& material, size_t index, SceneMaterial& out) {
    const std::string where = path_ + ": " + (material.name.empty() ? "material " + std::to_string(index)
                                                                     : "material '" + material.name + "'");
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    const auto slot = [&](uint32_t slot_index, const auto& info, bool srgb, const char* name) {
        const auto transform = info.extensions.find("KHR_texture_transform");
        out.textures[slot_index] =
            reference(info.index, info.texCoord, transform == info.extensions.end() ? nullptr : &transform->second,
                      srgb, where + ": " + name);
    };
    slot(WF_TEXTURE_BASE_COLOR, pbr.baseColorTexture, true, "baseColorTexture");
    slot(WF_TEXTURE_METALLIC_ROUGHNESS, pbr.metallicRoughnessTexture, false, "metallicRoughnessTexture");
    slot(WF_TEXTURE_NORMAL, material.normalTexture, false, "normalTexture");
    slot(WF_TEXTURE_EMISSIVE, material.emissiveTexture, true, "emissiveTexture");
    const auto extension_slot = [&](uint32_t slot_index, const char* extension, const char* property, bool srgb) {
        out.textures[slot_index] = extension_reference(material, extension, property, srgb, where);
    };
    extension_slot(WF_TEXTURE_SPECULAR, "KHR_materials_specular", "specularTexture", false);
    extension_slot(WF_TEXTURE_SPECULAR_COLOR, "KHR_materials_specular", "specularColorTexture", true);
    extension_slot(WF_TEXTURE_TRANSMISSION, "KHR_materials_transmission", "transmissionTexture", false);
    extension_slot(WF_TEXTURE_CLEARCOAT, "KHR_materials_clearcoat", "clearcoatTexture", false);
    extension_slot(WF_TEXTURE_CLEARCOAT_ROUGHNESS, "KHR_materials_clearcoat", "clearcoatRoughnessTexture", false);
    extension_slot(WF_TEXTURE_SHEEN_COLOR, "KHR_materials_sheen", "sheenColorTexture", true);
    extension_slot(WF_TEXTURE_SHEEN_ROUGHNESS, "KHR_materials_sheen", "sheenRoughnessTexture", false);

    out.normal_scale = to_float(material.normalTexture.scale, where, "normalTexture.scale");
    const double alpha = pbr.baseColorFactor.size() == 4 ? pbr.baseColorFactor[3] : 1.0;
    if (!(alpha >= 0.0 && alpha <= 1.0)) fail(where, "baseColorFactor alpha is not in [0, 1]");
    out.base_alpha = float(alpha);
    if (material.alphaMode == "OPAQUE" || material.alphaMode.empty()) {
        out.alpha_mode = WF_ALPHA_OPAQUE;
    } else if (material.alphaMode == "MASK") {
        if (!(material.alphaCutoff >= 0.0)) fail(where, "alphaCutoff must be non-negative");
        out.alpha_mode = WF_ALPHA_MASK;
        out.alpha_cutoff = to_float(material.alphaCutoff, where, "alphaCutoff");
    } else if (material.alphaMode == "BLEND") {
        out.alpha_mode = WF_ALPHA_MASK;
        out.alpha_cutoff = 0.5f;
        ++blend_materials_;
    } else {
        fail(where, "alphaMode '" + material.alphaMode + "' is not OPAQUE, MASK or BLEND");
    }
    occlusion_materials_ += material.occlusionTexture.index >= 0;
}

} // namespace wf
