/* emissive_triangles.h — next-event estimation on emissive triangles: choose a
 * triangle by power from the alias table, a point uniformly on it, and express
 * the density in solid angle at the receiver (area pdf · r² / cos θ′). The same
 * conversion gives the density with which light sampling would have produced a
 * direction that BRDF sampling found, for the MIS weight. */
#ifndef WF_EMISSIVE_TRIANGLES_H
#define WF_EMISSIVE_TRIANGLES_H

#include "wavefront/scene_types.h"
#include "common/sampling.h"
#include "geometry/ray_offset.h"

typedef struct LightSample {
    float3 point;
    float3 point_error; /* per component, as geometry/ray_offset.h bounds it */
    float3 normal;    /* unit, of the emitting face toward the receiver */
    float3 radiance;  /* Le toward the receiver; zero when its back faces it */
    float pdf;        /* solid angle at the receiver; 0 when unusable */
} LightSample;

inline uint choose_light(__global const LightEntry* lights, uint count, float u_index, float u_alias) {
    const uint i = min((uint)(u_index * (float)count), count - 1u);
    return u_alias < lights[i].probability ? i : lights[i].alias;
}

/* Solid-angle density of reaching a light point at distance² dist2 whose
 * surface makes cosine cos_light with the ray; 0 where it would overflow. */
inline float light_pdf_solid_angle(float pmf, float area, float dist2, float cos_light) {
    const float pdf = pmf * dist2 / (area * cos_light);
    return (cos_light > 0.0f && area > 0.0f && pdf < INFINITY) ? pdf : 0.0f;
}

inline LightSample sample_light(__global const LightEntry* lights, uint count,
                                __global const Triangle* triangles,
                                __global const Material* materials, float3 receiver, float4 u) {
    LightSample s;
    s.pdf = 0.0f;
    const LightEntry entry = lights[choose_light(lights, count, u.x, u.w)];
    const __global Triangle* t = &triangles[entry.triangle];
    const float3 v0 = vload3(0, t->v0), v1 = vload3(0, t->v1), v2 = vload3(0, t->v2);
    const float2 b = sample_triangle_uniform(u.yz);
    s.point = interpolate_triangle(v0, v1, v2, b.x, b.y);
    s.point_error = interpolation_error(v0, v1, v2, b.x, b.y);
    const float3 cross_edges = cross(v1 - v0, v2 - v0);
    const float area = 0.5f * length(cross_edges);
    const float3 to_receiver = receiver - s.point;
    const float dist2 = dot(to_receiver, to_receiver);
    const float3 front = cross_edges / (2.0f * area);
    const float cos_front = dot(front, to_receiver) / sqrt(dist2);
    const __global Material* m = &materials[t->material];
    const bool emits_toward = cos_front > 0.0f || (m->flags & WF_MATERIAL_DOUBLE_SIDED);
    s.normal = cos_front >= 0.0f ? front : -front;
    s.radiance = emits_toward ? vload3(0, m->emission) : (float3)(0.0f);
    s.pdf = emits_toward ? light_pdf_solid_angle(entry.pmf, area, dist2, fabs(cos_front)) : 0.0f;
    return s;
}

#endif
