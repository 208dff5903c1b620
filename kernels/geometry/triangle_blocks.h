/* triangle_blocks.h — one triangle read back from the blocks of four that the
 * leaf test loads a row at a time (include/wavefront/scene_types.h): what
 * shading and light sampling need of the triangle at one BVH position. Shared
 * by the kernels and the host. */
#ifndef WF_TRIANGLE_BLOCKS_H
#define WF_TRIANGLE_BLOCKS_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"

WF_DEVICE_BEGIN

WF_INLINE WF_GLOBAL const TriangleBlock* block_of(WF_GLOBAL const TriangleBlock* blocks, uint32_t position) {
    return blocks + position / WF_BLOCK_LANES;
}

/* Corner c (0, 1 or 2) of the triangle at `position`. */
WF_INLINE float3 triangle_corner(WF_GLOBAL const TriangleBlock* blocks, uint32_t position, int c) {
    WF_GLOBAL const TriangleBlock* b = block_of(blocks, position);
    const uint32_t lane = position % WF_BLOCK_LANES;
    return make_float3(b->corners[3 * c][lane], b->corners[3 * c + 1][lane], b->corners[3 * c + 2][lane]);
}

WF_INLINE uint32_t triangle_material(WF_GLOBAL const TriangleBlock* blocks, uint32_t position) {
    return block_of(blocks, position)->material[position % WF_BLOCK_LANES];
}

/* Its entry in the light table, or -1 when it does not emit. */
WF_INLINE int32_t triangle_light(WF_GLOBAL const TriangleBlock* blocks, uint32_t position) {
    return block_of(blocks, position)->light[position % WF_BLOCK_LANES];
}

WF_DEVICE_END

#endif /* WF_TRIANGLE_BLOCKS_H */
