// textured_emission.h — how bright an emissive texture is on one triangle,
// for the light table's powers (device_scene.cpp): the mean of the texture
// over the texels that the kernels' lookups on that triangle can read
// (kernels/materials/texture.h). Light choice by power then leaves out the
// triangles whose texels are all black, which emit nothing, and picks the
// rest by what they give: ToyCar's emissive map is black on 87% of its
// texels, and its 88 837 emissive triangles were all chosen by area alone.
//
// The footprint is the box around the triangle's three texture coordinates
// (after KHR_texture_transform), widened by the bilinear filter's reach and
// a texel more for the kernels' rounding, and wrapped as the sampler wraps.
// Its mean is summed texel by texel where the box is small, and from sums
// over 8×8 blocks of texels where it is large (the blocks that cover it, so
// the mean is an estimate there; a zero is still exact, since no texel is
// negative); a texture's block sums are made the first time a footprint
// needs them, not for every emissive texture at start-up.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace wf {

class TexturedEmission {
public:
    explicit TexturedEmission(const Scene& scene);

    // The mean linear RGB of triangle t's emissive texture over its
    // footprint, (1, 1, 1) where its material has none. Exactly 0 in a
    // channel only where every texel the kernels can read on the triangle
    // is 0 in it.
    glm::dvec3 mean(uint32_t t) const;

private:
    // Sums of a texture's decoded texels over 8×8 blocks, as a summed-area
    // table: (blocks_x + 1) × (blocks_y + 1) entries, row by row.
    struct BlockSums {
        uint32_t blocks_x = 0, blocks_y = 0;
        std::vector<glm::dvec3> table;
    };

    // Texture `texture`'s, summed the first time a large footprint needs them.
    const BlockSums& block_sums(int32_t texture) const;

    const Scene& scene_;
    mutable std::vector<BlockSums> block_sums_; // per TextureInfo; empty until needed
};

} // namespace wf
