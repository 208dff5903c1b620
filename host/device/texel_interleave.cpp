// texel_interleave.cpp — images are known by where their texels start in
// scene.textures (several TextureInfos may share one image); the new buffer
// takes them in that order, a group whole where its first image was.
#include "device/texel_interleave.h"

#include <cstring>
#include <map>
#include <set>

namespace wf {
namespace {

// Whether two references read their images at the same texel for every hit.
bool same_texel(const TextureRef& a, const TextureInfo& ia, const TextureRef& b, const TextureInfo& ib) {
    return a.texcoord == b.texcoord && std::memcmp(a.transform, b.transform, sizeof a.transform) == 0 &&
           ia.width == ib.width && ia.height == ib.height && ia.wrap_s == ib.wrap_s && ia.wrap_t == ib.wrap_t;
}

// The groups of images (by their first texel in scene.textures), two or more each.
std::vector<std::vector<uint32_t>> image_groups(const Scene& scene) {
    const std::vector<TextureInfo>& infos = scene.textures.infos;
    std::vector<std::vector<uint32_t>> groups;
    std::set<uint32_t> placed;
    for (const SceneMaterial& m : scene.materials) {
        std::vector<const TextureRef*> firsts; // one reference per candidate group of this material
        std::vector<std::vector<uint32_t>> candidates;
        std::set<uint32_t> taken; // by a candidate: an image read twice, at two texels, goes with the first
        for (const TextureRef& ref : m.textures) {
            if (ref.texture < 0) continue;
            const TextureInfo& info = infos[size_t(ref.texture)];
            if (placed.count(info.offset) || !taken.insert(info.offset).second) continue;
            size_t g = 0;
            while (g < firsts.size() &&
                   !same_texel(*firsts[g], infos[size_t(firsts[g]->texture)], ref, info))
                ++g;
            if (g == firsts.size()) {
                firsts.push_back(&ref);
                candidates.emplace_back();
            }
            candidates[g].push_back(info.offset);
        }
        for (std::vector<uint32_t>& c : candidates) {
            if (c.size() < 2) continue;
            placed.insert(c.begin(), c.end());
            groups.push_back(std::move(c));
        }
    }
    return groups;
}

} // namespace

InterleavedTexels interleave_texels(const Scene& scene) {
    const std::vector<TextureInfo>& infos = scene.textures.infos;
    const std::vector<uint32_t>& texels = scene.textures.texels;
    std::map<uint32_t, uint32_t> image_texels; // first texel → texel count
    for (const TextureInfo& info : infos) image_texels[info.offset] = info.width * info.height;
    const std::vector<std::vector<uint32_t>> groups = image_groups(scene);
    std::map<uint32_t, const std::vector<uint32_t>*> group_of;
    for (const std::vector<uint32_t>& g : groups)
        for (const uint32_t image : g) group_of[image] = &g;

    struct Place {
        uint32_t offset, stride;
    };
    std::map<uint32_t, Place> place; // first texel in scene.textures → where it is now
    InterleavedTexels out;
    out.texels.reserve(texels.size());
    for (const auto& [image, count] : image_texels) {
        if (place.count(image)) continue;
        const auto base = uint32_t(out.texels.size());
        const auto found = group_of.find(image);
        if (found == group_of.end()) {
            place[image] = {base, 1};
            out.texels.insert(out.texels.end(), texels.begin() + image, texels.begin() + image + count);
            continue;
        }
        const std::vector<uint32_t>& g = *found->second;
        const auto stride = uint32_t(g.size());
        out.texels.resize(out.texels.size() + size_t{count} * stride);
        for (uint32_t j = 0; j < stride; ++j) {
            place[g[j]] = {base + j, stride};
            for (uint32_t i = 0; i < count; ++i) out.texels[base + size_t{i} * stride + j] = texels[g[j] + i];
        }
    }
    out.infos = infos;
    for (TextureInfo& info : out.infos) {
        const Place p = place.at(info.offset);
        info.offset = p.offset;
        info.stride = p.stride;
    }
    return out;
}

} // namespace wf
