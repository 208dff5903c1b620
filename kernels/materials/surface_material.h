/* surface_material.h — a material at one point of one triangle: its glTF
 * factors times its textures (materials/surface_texture.h), as the shade
 * stage and light sampling need them: the BSDF's parameters, the emitted
 * radiance (through the clear coat), and the normal-mapped shading normal.
 * Device only. */
#ifndef WF_SURFACE_MATERIAL_H
#define WF_SURFACE_MATERIAL_H

#include "wavefront/compat.h"
#include "bsdf/bsdf.h"
#include "materials/surface_texture.h"
#include "materials/valid_reflection.h"
#include "materials/vertex_color.h"
#include "geometry/instance_map.h"

/* The clear coat's weight: its factor times its texture's red. */
WF_INLINE float surface_clearcoat(__global const Material* m, const Scene* scene, const SurfacePoint* p) {
    return WF_HAS_CLEARCOAT && m->clearcoat > 0.0f ? m->clearcoat * surface_texture(scene, p, WF_TEXTURE_CLEARCOAT).x
                                                   : 0.0f;
}

WF_INLINE BsdfParams surface_bsdf(__global const Material* m, const Scene* scene, const SurfacePoint* p,
                               uint hemisphere) {
    const float4 base = surface_texture(scene, p, WF_TEXTURE_BASE_COLOR);
    const float4 metallic_roughness = surface_texture(scene, p, WF_TEXTURE_METALLIC_ROUGHNESS);
    BsdfParams b;
#if WF_GLASS_TABLE_IN_SCENE
    b.glass_table = scene->glass_albedo;
#endif
    b.base_color = vload3(0, m->base_color) * base.xyz * surface_vertex_color(scene, p).xyz;
    b.metallic = m->metallic * metallic_roughness.z;
    b.roughness = m->roughness * metallic_roughness.y;
    b.transmission = m->transmission * surface_texture(scene, p, WF_TEXTURE_TRANSMISSION).x;
    b.ior = m->ior;
    b.specular = m->specular * surface_texture(scene, p, WF_TEXTURE_SPECULAR).w;
    b.specular_color = vload3(0, m->specular_color) * surface_texture(scene, p, WF_TEXTURE_SPECULAR_COLOR).xyz;
    b.thin_walled = m->thin_walled != 0.0f;
    b.clearcoat = surface_clearcoat(m, scene, p);
    b.clearcoat_roughness = m->clearcoat_roughness;
    if (WF_HAS_CLEARCOAT && m->clearcoat > 0.0f)
        b.clearcoat_roughness *= surface_texture(scene, p, WF_TEXTURE_CLEARCOAT_ROUGHNESS).y;
    b.sheen_color = vload3(0, m->sheen_color);
    b.sheen_roughness = m->sheen_roughness;
    if (WF_HAS_SHEEN && any(b.sheen_color > 0.0f)) {
        b.sheen_color *= surface_texture(scene, p, WF_TEXTURE_SHEEN_COLOR).xyz;
        b.sheen_roughness *= surface_texture(scene, p, WF_TEXTURE_SHEEN_ROUGHNESS).w;
    }
    b.hemisphere = hemisphere;
    return b;
}

/* x turned to the side of ng; the dot product written out as the lanes'
 * vec_dot is (stages/surface.inc), so both turn it alike. */
WF_INLINE float3 facing(float3 x, float3 ng) { return x.x * ng.x + x.y * ng.y + x.z * ng.z < 0.0f ? -x : x; }

/* The shading normal, on the side of ng (the unit geometric normal on the side
 * the ray arrived from, v the unit way back along it): the interpolated normal
 * n (unit, front-facing as the mesh gives it) bent by the material's normal
 * map, if any: tangent-space (2c - 1) with x and y scaled by
 * normalTexture.scale, in the frame of the interpolated tangent made
 * orthogonal to n and the bitangent cross(n, t) w. A mapped normal that would
 * mirror v into the surface is bent back (materials/valid_reflection.h);
 * interpolated ones are left as the mesh gives them. */
WF_INLINE float3 surface_normal(const Scene* scene, const SurfacePoint* p, float3 n, float3 ng, float3 v) {
#if WF_HAS_NORMAL_MAPS
    __global const TextureRef* ref = texture_slot(scene, p->material, WF_TEXTURE_NORMAL);
    if (ref->texture < 0) return facing(n, ng);
    const float4 c = surface_texture(scene, p, WF_TEXTURE_NORMAL);
    const float scale = scene->material_textures[p->material].normal_scale;
    const float3 in_tangent_space = (float3)((2.0f * c.x - 1.0f) * scale, (2.0f * c.y - 1.0f) * scale, 2.0f * c.z - 1.0f);
    __global const TriangleTangents* t = &scene->tangents[p->triangle];
    const float b0 = 1.0f - p->b1 - p->b2;
    float4 tangent = b0 * vload4(0, t->t0) + p->b1 * vload4(0, t->t1) + p->b2 * vload4(0, t->t2);
#if WF_HAS_INSTANCES
    /* A placement's tangent moves with its surface, and a mirror flips its handedness. */
    if (p->instance >= 0) {
        __global const Instance* placement = scene->instances + p->instance;
        tangent = (float4)(map_vector(placement->object_to_world, tangent.xyz), tangent.w * placement->handedness);
    }
#endif
    const float3 along = tangent.xyz - dot(tangent.xyz, n) * n;
    const float length_along = length(along);
    float3 mapped = n; /* where the tangent frame or the bent normal degenerates */
    if (length_along > 0.0f) {
        const float3 x = along / length_along;
        const float3 y = cross(n, x) * (tangent.w < 0.0f ? -1.0f : 1.0f);
        const float3 bent = in_tangent_space.x * x + in_tangent_space.y * y + in_tangent_space.z * n;
        const float length_bent = length(bent);
        if (length_bent > 0.0f && dot(bent, n) > 0.0f) mapped = bent / length_bent;
    }
    return valid_reflection_normal(ng, v, facing(mapped, ng));
#else
    return facing(n, ng);
#endif
}

/* surface_normal at the point, from the triangle's interpolated normals. */
WF_INLINE float3 surface_shading_normal(const Scene* scene, const SurfacePoint* p, float3 ng, float3 v) {
    __global const TriangleNormals* n = &scene->normals[p->triangle];
    const float b0 = 1.0f - p->b1 - p->b2;
    const float3 interpolated = normalize(b0 * vload3(0, n->n0) + p->b1 * vload3(0, n->n1) + p->b2 * vload3(0, n->n2));
    return surface_normal(scene, p, interpolated, ng, v);
}

/* Radiance emitted at the point toward v (unit; ng the unit geometric normal
 * on its side), through the clear coat if there is one (bsdf/coat_fresnel.h):
 * the one rule for emission that rays find and that light sampling draws. */
WF_INLINE float3 surface_emission(__global const Material* m, const Scene* scene, const SurfacePoint* p, float3 ng,
                                  float3 v) {
    const float3 emission = vload3(0, m->emission) * surface_texture(scene, p, WF_TEXTURE_EMISSIVE).xyz;
    if (!WF_HAS_CLEARCOAT || !(m->clearcoat > 0.0f)) return emission;
    const float mu_o = dot(surface_shading_normal(scene, p, ng, v), v);
    return coat_emission_weight(surface_clearcoat(m, scene, p), mu_o) * emission;
}

#endif
