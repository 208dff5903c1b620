// gltf_textures.h — a glTF material's textures: which images it reads, under
// which samplers, with which texture coordinates and KHR_texture_transform,
// plus its normal scale and alpha mode. Called by the glTF loader once per
// material; fills SceneMaterial's texture fields and the Scene's TextureSet.
//
// Conventions:
// - base colour, emissive, specular colour and sheen colour images are sRGB,
//   the others linear (glTF 2.0 §3.9 and the extensions); occlusion is not
//   read (a path tracer computes its own);
// - an image is decoded once however many textures use it; each (image,
//   sampler, colour space) gets one TextureInfo;
// - texCoord 0 and 1 are supported; a higher set warns and reads TEXCOORD_0;
// - alpha BLEND is loaded as MASK with cutoff 0.5 (a path tracer has no draw
//   order to blend in; an opaque sheet would hide what lies behind cut-out
//   foliage and decals, which most BLEND materials are), with one warning;
// - a missing or undecodable image is an InputError naming the file, the
//   material, the texture slot and the image (index and uri or name).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Model;
struct Material;
struct Image;
class Value;
} // namespace tinygltf

namespace wf {

// tinygltf's image callback: keeps each image's encoded bytes in
// Image::image with as_is set, decoding nothing; GltfTextures decodes the
// images a material uses. A file tinygltf could not read leaves image empty.
bool keep_image_encoded(tinygltf::Image* image, int index, std::string* error, std::string* warning,
                        int width, int height, const unsigned char* bytes, int size, void* user);

class GltfTextures {
public:
    // `path`: the glTF file, for messages. `set` receives the textures.
    GltfTextures(const tinygltf::Model& model, const std::string& path, TextureSet& set);

    // Sets `out`'s textures, normal_scale, alpha_mode, alpha_cutoff and base_alpha.
    void convert(const tinygltf::Material& material, size_t index, SceneMaterial& out);

    // The warnings gathered over all materials, each said once.
    std::vector<std::string> warnings() const;

private:
    int32_t texture_info(int index, bool srgb, const std::string& where);
    // `transform`: the textureInfo's KHR_texture_transform object, or null.
    TextureRef reference(int index, int tex_coord, const tinygltf::Value* transform, bool srgb,
                         const std::string& where);
    // A textureInfo inside a material extension (tinygltf parses only the core ones).
    TextureRef extension_reference(const tinygltf::Material& material, const char* extension, const char* property,
                                   bool srgb, const std::string& where);

    const tinygltf::Model& model_;
    std::string path_;
    TextureSet& set_;
    std::vector<int64_t> image_offsets_;     // by glTF image; -1 until decoded
    std::vector<std::vector<int32_t>> infos_; // by glTF texture: (srgb) -> TextureInfo, -1 until made
    std::vector<std::array<uint32_t, 3>> decoded_sizes_; // by glTF image: width, height, channels
    size_t blend_materials_ = 0;
    size_t occlusion_materials_ = 0;
    size_t high_texcoords_ = 0;
};

} // namespace wf
