// textured_emission.cpp — the mean of an emissive texture over a triangle's
// footprint (textured_emission.h), read through the kernels' own texel
// decoding and wrapping (kernels/materials/texture.h), so that "all black"
// here is "all black" there.
#include "device/textured_emission.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "materials/texture.h"

namespace wf {
namespace {

constexpr uint32_t kBlock = 8;            // texels a side of a block of BlockSums
constexpr double kExactTexels = 4096.0;   // footprints up to this many texels are summed texel by texel

using Run = std::pair<uint32_t, uint32_t>; // texel indices [first, last] along one axis

glm::dvec3 texel_rgb(const TextureInfo& info, const std::vector<uint32_t>& texels, uint32_t x, uint32_t y) {
    const wf_device::float4 c = wf_device::texture_texel(&info, texels.data(), x, y);
    return glm::dvec3(c.x, c.y, c.z);
}

// The texel indices along one axis of `size` texels that a lookup at any
// coordinate in [lo, hi] (in texels of the unwrapped plane, u * size) can
// read, as disjoint runs in increasing order: the bilinear filter reads
// floor(x - 0.5) and the texel after it, NEAREST floor(x); `margin` texels
// more on each side cover the kernels' rounding of x.
std::vector<Run> axis_runs(double lo, double hi, double margin, uint32_t wrap_mode, uint32_t size) {
    const double first = std::floor(lo - 0.5 - margin), last = std::floor(hi + 0.5 + margin);
    const double n = size;
    if (wrap_mode == WF_WRAP_CLAMP_TO_EDGE) // clamping is monotone: the range's ends clamped
        return {{uint32_t(std::clamp(first, 0.0, n - 1.0)), uint32_t(std::clamp(last, 0.0, n - 1.0))}};
    if (!(last - first + 1.0 < 2.0 * n)) return {{0u, size - 1u}}; // a whole period of the wrap, or more
    // Between multiples of size the wrap is monotone (REPEAT rises, MIRRORED_REPEAT
    // rises and falls in turn), so each of the range's (at most three) pieces
    // reads the texels between its ends' wrapped indices.
    const auto wrap = [&](double i) {
        const double period = 2.0 * n; // of REPEAT's wrap too, being twice its own
        return wf_device::texture_wrap_index(int32_t(i - period * std::floor(i / period)), wrap_mode, size);
    };
    std::vector<Run> runs;
    for (double piece = std::floor(first / n) * n; piece <= last; piece += n) {
        const uint32_t a = wrap(std::max(first, piece)), b = wrap(std::min(last, piece + n - 1.0));
        runs.push_back({std::min(a, b), std::max(a, b)});
    }
    std::sort(runs.begin(), runs.end());
    std::vector<Run> merged;
    for (const Run& r : runs)
        if (!merged.empty() && r.first <= merged.back().second + 1u)
            merged.back().second = std::max(merged.back().second, r.second);
        else
            merged.push_back(r);
    return merged;
}

uint32_t texels_in(const std::vector<Run>& runs) {
    uint32_t count = 0;
    for (const Run& r : runs) count += r.second - r.first + 1u;
    return count;
}

// The runs of blocks that cover `runs`, merged where they meet.
std::vector<Run> block_runs(const std::vector<Run>& runs) {
    std::vector<Run> blocks;
    for (const Run& r : runs) {
        const Run b{r.first / kBlock, r.second / kBlock};
        if (!blocks.empty() && b.first <= blocks.back().second + 1u)
            blocks.back().second = std::max(blocks.back().second, b.second);
        else
            blocks.push_back(b);
    }
    return blocks;
}

} // namespace

TexturedEmission::TexturedEmission(const Scene& scene) : scene_(scene), block_sums_(scene.textures.infos.size()) {}

const TexturedEmission::BlockSums& TexturedEmission::block_sums(int32_t texture) const {
    BlockSums& sums = block_sums_[size_t(texture)];
    if (!sums.table.empty()) return sums;
    const TextureInfo& info = scene_.textures.infos[size_t(texture)];
    sums.blocks_x = (info.width + kBlock - 1u) / kBlock;
    sums.blocks_y = (info.height + kBlock - 1u) / kBlock;
    const size_t stride = sums.blocks_x + 1u;
    sums.table.assign(stride * (sums.blocks_y + 1u), glm::dvec3(0.0));
    for (uint32_t y = 0; y < info.height; ++y)
        for (uint32_t x = 0; x < info.width; ++x)
            sums.table[(y / kBlock + 1u) * stride + x / kBlock + 1u] += texel_rgb(info, scene_.textures.texels, x, y);
    for (size_t by = 1; by <= sums.blocks_y; ++by)
        for (size_t bx = 1; bx <= sums.blocks_x; ++bx)
            sums.table[by * stride + bx] += sums.table[(by - 1) * stride + bx] + sums.table[by * stride + bx - 1] -
                                            sums.table[(by - 1) * stride + bx - 1];
    return sums;
}

glm::dvec3 TexturedEmission::mean(uint32_t t) const {
    const SceneMaterial& m = scene_.materials[scene_.triangle_material[t]];
    const TextureRef& ref = m.textures[WF_TEXTURE_EMISSIVE];
    if (ref.texture < 0) return glm::dvec3(1.0);
    const TextureInfo& info = scene_.textures.infos[size_t(ref.texture)];
    const std::vector<glm::vec2>& uv = ref.texcoord == 1u ? scene_.uv1 : scene_.uv0;

    // The footprint's box in texels of the unwrapped plane; a coordinate
    // that is not finite (which the kernels read as 0) takes the whole texture.
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    bool finite = true;
    for (size_t k = 0; k < 3; ++k) {
        const glm::dvec2 c = uv.size() > 3 * size_t(t) + k ? glm::dvec2(uv[3 * size_t(t) + k]) : glm::dvec2(0.0);
        const glm::dvec2 st(ref.transform[0] * c.x + ref.transform[1] * c.y + ref.transform[2],
                            ref.transform[3] * c.x + ref.transform[4] * c.y + ref.transform[5]);
        finite = finite && std::isfinite(st.x) && std::isfinite(st.y);
        lo = glm::min(lo, st);
        hi = glm::max(hi, st);
    }
    const glm::dvec2 size(info.width, info.height);
    // The kernels' coordinate is the interpolation and transform in float:
    // a few ulps of its magnitude, here 2^-16 of it and a texel more.
    const glm::dvec2 margin = 1.0 + size * (glm::max(glm::abs(lo), glm::abs(hi)) + 1.0) * 0x1p-16;
    const std::vector<Run> xs = finite ? axis_runs(lo.x * size.x, hi.x * size.x, margin.x, info.wrap_s, info.width)
                                       : std::vector<Run>{{0u, info.width - 1u}};
    const std::vector<Run> ys = finite ? axis_runs(lo.y * size.y, hi.y * size.y, margin.y, info.wrap_t, info.height)
                                       : std::vector<Run>{{0u, info.height - 1u}};

    glm::dvec3 sum(0.0);
    double count = 0.0;
    if (double(texels_in(xs)) * texels_in(ys) <= kExactTexels) {
        for (const Run& ry : ys)
            for (uint32_t y = ry.first; y <= ry.second; ++y)
                for (const Run& rx : xs)
                    for (uint32_t x = rx.first; x <= rx.second; ++x) {
                        sum += texel_rgb(info, scene_.textures.texels, x, y);
                        ++count;
                    }
    } else {
        const BlockSums& sums = block_sums(ref.texture);
        const size_t stride = sums.blocks_x + 1u;
        for (const Run& by : block_runs(ys))
            for (const Run& bx : block_runs(xs)) {
                sum += sums.table[(by.second + 1u) * stride + bx.second + 1u] -
                       sums.table[by.first * stride + bx.second + 1u] -
                       sums.table[(by.second + 1u) * stride + bx.first] + sums.table[by.first * stride + bx.first];
                const uint32_t width = std::min((bx.second + 1u) * kBlock, info.width) - bx.first * kBlock;
                const uint32_t height = std::min((by.second + 1u) * kBlock, info.height) - by.first * kBlock;
                count += double(width) * height;
            }
    }
    // A sum of texels none of which is negative is 0 only when each of them
    // is; its differences in the table can round below 0 by a hair.
    return glm::max(sum / count, glm::dvec3(0.0));
}

} // namespace wf
