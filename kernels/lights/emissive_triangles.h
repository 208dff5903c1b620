/* emissive_triangles.h — the emissive-triangle part of next-event estimation:
 * a point uniformly on the chosen triangle, its density expressed in solid
 * angle at the receiver (area pdf · r² / cos θ′). The same conversion gives the
 * density with which light sampling would have produced a direction that BRDF
 * sampling found, for the MIS weight. */
#ifndef WF_EMISSIVE_TRIANGLES_H
#define WF_EMISSIVE_TRIANGLES_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"
#include "common/sampling.h"
#include "geometry/triangle_blocks.h"
#include "geometry/ray_offset.h"
#include "lights/light_sample.h"
#include "materials/alpha_mask.h"
#include "materials/surface_material.h"

/* Solid-angle density of reaching a light point at distance² dist2 whose
 * surface makes cosine cos_light with the ray; 0 where it would overflow. */
WF_INLINE float light_pdf_solid_angle(float pmf, float area, float dist2, float cos_light) {
    const float pdf = pmf * dist2 / (area * cos_light);
    return (cos_light > 0.0f && area > 0.0f && pdf < INFINITY) ? pdf : 0.0f;
}

/* A point on the triangle of `entry`, as seen from `receiver`. */
WF_INLINE LightSample sample_emissive_triangle(LightEntry entry, const Scene* scene, float3 receiver, float2 u) {
    LightSample s = no_light_sample();
    s.segment_end = WF_SEGMENT_TO_SURFACE;
    const float3 v0 = triangle_corner(scene->triangles, entry.index, 0);
    const float3 v1 = triangle_corner(scene->triangles, entry.index, 1);
    const float3 v2 = triangle_corner(scene->triangles, entry.index, 2);
    const uint material = triangle_material(scene->triangles, entry.index);
    const float2 b = sample_triangle_uniform(u);
    s.point = interpolate_triangle(v0, v1, v2, b.x, b.y);
    s.point_error = interpolation_error(v0, v1, v2, b.x, b.y);
    const float3 cross_edges = cross(v1 - v0, v2 - v0);
    const float area = 0.5f * length(cross_edges);
    const float3 to_receiver = receiver - s.point;
    const float dist2 = dot(to_receiver, to_receiver);
    const float distance = sqrt(dist2);
    s.wi = -to_receiver / distance;
    const float3 front = cross_edges / (2.0f * area);
    const float cos_front = dot(front, to_receiver) / distance;
    const __global Material* m = &scene->materials[material];
    const bool emits_toward = cos_front > 0.0f || (m->flags & WF_MATERIAL_DOUBLE_SIDED);
    s.normal = cos_front >= 0.0f ? front : -front;
    SurfacePoint point;
    point.triangle = entry.index;
    point.material = material;
    point.b1 = b.x;
    point.b2 = b.y;
    /* A point in an alpha-masked hole is not there: BSDF rays pass through it. */
    const bool present = hit_passes_filter(scene, scene->triangles, (int)entry.index, b.x, b.y);
    s.radiance = emits_toward && present ? surface_emission(m, scene, &point, s.normal, -s.wi) : (float3)(0.0f);
    s.pdf = emits_toward && present ? light_pdf_solid_angle(entry.pmf, area, dist2, fabs(cos_front)) : 0.0f;
    return s;
}

#endif
