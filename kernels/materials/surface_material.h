/* surface_material.h — a material at one point of one triangle: its glTF
 * factors times its textures (materials/texture.h), as the shade stage and
 * light sampling need them: the BSDF's parameters, the emitted radiance, and
 * the normal-mapped shading normal. A material without textures reads its
 * factors alone and never touches the texture coordinates (which scenes
 * without textures do not upload). */
#ifndef WF_SURFACE_MATERIAL_H
#define WF_SURFACE_MATERIAL_H

#include "wavefront/scene_types.h"
#include "compiled_features.h"
#include "bsdf/bsdf.h"
#include "materials/texture.h"

/* The scene's texture buffers, gathered so they travel as one argument. */
typedef struct SceneTextures {
    __global const TextureInfo* infos;
    __global const uint* texels;
    __global const TextureRef* refs;               /* WF_TEXTURE_SLOTS per material */
    __global const MaterialTextureParams* params;  /* one per material */
    __global const TriangleTexcoords* texcoords;   /* per triangle, BVH order */
    __global const TriangleTangents* tangents;
} SceneTextures;

/* The texture buffers as kernel parameters, in the order the host sets them
 * (host/integrator/wavefront_scheduler.cpp), and gathered into one SceneTextures. */
#define WF_SCENE_TEXTURE_PARAMS                                                                              \
    __global const TextureInfo *texture_infos, __global const uint *texels,                                  \
        __global const TextureRef *texture_refs, __global const MaterialTextureParams *material_textures,    \
        __global const TriangleTexcoords *texcoords, __global const TriangleTangents *tangents
#define WF_BIND_SCENE_TEXTURES(name)                                                                         \
    const SceneTextures name = {texture_infos, texels, texture_refs, material_textures, texcoords, tangents}

/* Where on a triangle, for texture lookups: its index and the barycentrics
 * of corners 1 and 2. */
typedef struct SurfacePoint {
    uint triangle;
    uint material;
    float b1, b2;
} SurfacePoint;

inline __global const TextureRef* texture_slot(const SceneTextures* tx, uint material, uint slot) {
    return &tx->refs[material * WF_TEXTURE_SLOTS + slot];
}

/* The slot's texture at the point, or (1, 1, 1, 1) when the slot has none. */
inline float4 surface_texture(const SceneTextures* tx, const SurfacePoint* p, uint slot) {
#if WF_HAS_TEXTURES
    __global const TextureRef* ref = texture_slot(tx, p->material, slot);
    if (ref->texture < 0) return (float4)(1.0f);
    __global const float* uv = ref->texcoord == 0u ? tx->texcoords[p->triangle].uv0 : tx->texcoords[p->triangle].uv1;
    const float b0 = 1.0f - p->b1 - p->b2;
    const float2 st = b0 * vload2(0, uv) + p->b1 * vload2(1, uv) + p->b2 * vload2(2, uv);
    return texture_sample(tx->infos, tx->texels, ref, st);
#else
    return (float4)(1.0f);
#endif
}

inline BsdfParams surface_bsdf(__global const Material* m, const SceneTextures* tx, const SurfacePoint* p,
                               uint hemisphere) {
    const float4 base = surface_texture(tx, p, WF_TEXTURE_BASE_COLOR);
    const float4 metallic_roughness = surface_texture(tx, p, WF_TEXTURE_METALLIC_ROUGHNESS);
    BsdfParams b;
    b.base_color = vload3(0, m->base_color) * base.xyz;
    b.metallic = m->metallic * metallic_roughness.z;
    b.roughness = m->roughness * metallic_roughness.y;
    b.transmission = m->transmission;
    b.ior = m->ior;
    b.specular = m->specular;
    b.hemisphere = hemisphere;
    return b;
}

/* Radiance emitted by the front face at the point. */
inline float3 surface_emission(__global const Material* m, const SceneTextures* tx, const SurfacePoint* p) {
    return vload3(0, m->emission) * surface_texture(tx, p, WF_TEXTURE_EMISSIVE).xyz;
}

/* The shading normal n (unit, front-facing as the mesh gives it) bent by the
 * material's normal map, if any: tangent-space (2c - 1) with x and y scaled
 * by normalTexture.scale, in the frame of the interpolated tangent made
 * orthogonal to n and the bitangent cross(n, t) w. */
inline float3 surface_normal(const SceneTextures* tx, const SurfacePoint* p, float3 n) {
#if WF_HAS_NORMAL_MAPS
    __global const TextureRef* ref = texture_slot(tx, p->material, WF_TEXTURE_NORMAL);
    if (ref->texture < 0) return n;
    const float4 c = surface_texture(tx, p, WF_TEXTURE_NORMAL);
    const float scale = tx->params[p->material].normal_scale;
    const float3 in_tangent_space = (float3)((2.0f * c.x - 1.0f) * scale, (2.0f * c.y - 1.0f) * scale, 2.0f * c.z - 1.0f);
    __global const TriangleTangents* t = &tx->tangents[p->triangle];
    const float b0 = 1.0f - p->b1 - p->b2;
    const float4 tangent = b0 * vload4(0, t->t0) + p->b1 * vload4(0, t->t1) + p->b2 * vload4(0, t->t2);
    const float3 along = tangent.xyz - dot(tangent.xyz, n) * n;
    const float length_along = length(along);
    if (!(length_along > 0.0f)) return n;
    const float3 x = along / length_along;
    const float3 y = cross(n, x) * (tangent.w < 0.0f ? -1.0f : 1.0f);
    const float3 bent = in_tangent_space.x * x + in_tangent_space.y * y + in_tangent_space.z * n;
    const float length_bent = length(bent);
    return length_bent > 0.0f && dot(bent, n) > 0.0f ? bent / length_bent : n;
#else
    return n;
#endif
}

#endif
