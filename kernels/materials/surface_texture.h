/* surface_texture.h — a material's texture at one point of one triangle
 * (materials/texture.h does the lookup): what the shade stage's material
 * (materials/surface_material.h) and the BVH's alpha test
 * (materials/alpha_mask.h) both read. Knows textures, not BSDFs. A material
 * without textures reads (1, 1, 1, 1) and never touches the texture
 * coordinates, which scenes without textures do not upload. Device only. */
#ifndef WF_SURFACE_TEXTURE_H
#define WF_SURFACE_TEXTURE_H

#include "wavefront/compat.h"
#include "compiled_features.h"
#include "scene_view.h"
#include "materials/texture.h"

/* Where on a triangle, for texture lookups: its index and the barycentrics
 * of corners 1 and 2. */
typedef struct SurfacePoint {
    uint triangle;
    uint material;
    float b1, b2;
#if WF_HAS_INSTANCES
    int instance; /* the placement whose triangle it is, where the normal map's tangent needs its map */
#endif
} SurfacePoint;

WF_INLINE __global const TextureRef* texture_slot(const Scene* scene, uint material, uint slot) {
    return &scene->texture_refs[material * WF_TEXTURE_SLOTS + slot];
}

/* The slot's texture at the point, or (1, 1, 1, 1) when the slot has none. */
WF_INLINE float4 surface_texture(const Scene* scene, const SurfacePoint* p, uint slot) {
#if WF_HAS_TEXTURES
    __global const TextureRef* ref = texture_slot(scene, p->material, slot);
    if (ref->texture < 0) return (float4)(1.0f);
    __global const float* uv =
        ref->texcoord == 0u ? scene->texcoords[p->triangle].uv0 : scene->texcoords[p->triangle].uv1;
    const float b0 = 1.0f - p->b1 - p->b2;
    const float2 st = b0 * vload2(0, uv) + p->b1 * vload2(1, uv) + p->b2 * vload2(2, uv);
    return texture_sample(scene->texture_infos, scene->texels, ref, st);
#else
    return (float4)(1.0f);
#endif
}

#endif
