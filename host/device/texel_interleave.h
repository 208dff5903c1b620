// texel_interleave.h — the device's texel buffer, with the images a material
// reads at the same texel stored texel by texel side by side.
//
// Why: a hit on a textured material reads each of its textures (base colour,
// metallic-roughness, normal, emissive, clear coat, ...) at one texture
// coordinate, four texels each. Stored one image after another, those reads
// touch two cache lines per image, scattered over megabytes; once the paths
// have bounced, each is a miss (on ToyCar, texture_sample waits on its first
// texel row most of its time). Interleaved, texel (x, y) of every image of
// the group sits in a few consecutive words, and one material's reads share
// their lines. The bytes are the same; TextureInfo::stride says how far apart
// one image's texels are (kernels/materials/texture.h).
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace wf {

// The scene's texels and TextureInfos (scene.textures) with images grouped:
// the images one material reads through its texture slots with the same
// texture coordinate set, transform, size and wrap modes form a group, each
// image in the first group it falls in (materials in order); every other
// image keeps its texels together (stride 1). Every TextureInfo reads the
// same values as scene.textures' does, at every texel.
struct InterleavedTexels {
    std::vector<TextureInfo> infos;
    std::vector<uint32_t> texels;
};
InterleavedTexels interleave_texels(const Scene& scene);

} // namespace wf
