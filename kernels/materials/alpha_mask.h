/* alpha_mask.h — glTF's alpha MASK mode as the BVH traversal applies it
 * (geometry/bvh_traverse.h): a hit on a masked material counts only where the
 * base colour's alpha (factor times texture times COLOR_0) reaches the cutoff, for closest
 * hits and shadow rays alike, so a cut-out leaf neither shows nor casts a
 * shadow where it is transparent. Device only: the host's traversal (for the
 * tests) has no textures and passes every hit. */
#ifndef WF_ALPHA_MASK_H
#define WF_ALPHA_MASK_H

#include "wavefront/compat.h"
#include "geometry/triangle_blocks.h"
#include "materials/surface_texture.h"
#include "materials/vertex_color.h"

/* The scene, whose textures say where a masked material is opaque. */
typedef Scene HitFilter;

WF_INLINE int hit_passes_filter(const HitFilter* scene, __global const TriangleBlock* triangles, int triangle, float b1,
                             float b2) {
#if WF_HAS_ALPHA_MASK
    const uint material = triangle_material(triangles, (uint)triangle);
    const MaterialTextureParams p = scene->material_textures[material];
    if (p.alpha_mode != WF_ALPHA_MASK) return 1;
    SurfacePoint point;
    point.triangle = (uint)triangle;
    point.material = material;
    point.b1 = b1;
    point.b2 = b2;
#if WF_HAS_INSTANCES
    point.instance = -1; /* the mask reads no tangent */
#endif
    return p.base_alpha * surface_texture(scene, &point, WF_TEXTURE_BASE_COLOR).w *
               surface_vertex_color(scene, &point).w >=
           p.alpha_cutoff;
#else
    return 1;
#endif
}

#endif
