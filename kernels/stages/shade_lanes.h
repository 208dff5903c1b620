/* shade_lanes.h — the lane path of shade (stages/shade.h), for the group
 * schedule: the shading points of a work-group,
 * gathered into a structure of arrays in local memory (shade_lanes_put, one
 * path a work-item, after shade_surface), their light sample, BSDF core and
 * scatter run WF_LANE_WIDTH at a time by the width-generic code
 * (shade_lanes_run, one work-item a run of lanes: lights/light_lanes.inc,
 * bsdf/kinds/layered.inc, stages/scatter.inc), and each path's scatter read
 * back (shade_lanes_get) for write_scatter. The light sample is taken in
 * lanes where every light is an emissive triangle whose emission is its
 * material's factor (WF_LIGHTS_IN_LANES), else by shade_light a path at a
 * time. The lanes draw each path's BSDF numbers (shade_lanes_numbers). Where
 * no texture shapes a surface and no material has a coat or sheen
 * (WF_SURFACE_IN_LANES), every hit is put right after its arrival
 * (shade_lanes_put_arrival) and the lanes also find its surface
 * (stages/surface.inc) and draw its light's numbers; the emission it found
 * comes back with its scatter (shade_lanes_emission). Its answers are width 1's to the bit
 * (tests/kernels/test_bsdf_kinds.cpp, tests/integrator/test_determinism.cpp),
 * so the group schedule makes the megakernel's bytes. The functions that take
 * the lanes' local memory are WF_GPU_INLINE: left as calls in a GPU's program
 * (--kernels gpu --lane-width 8 on PoCL 3.1), every path ended at its first
 * hit. Device only. */
#ifndef WF_SHADE_LANES_H
#define WF_SHADE_LANES_H

#include "wavefront/compat.h"
#include "bsdf/kinds.h"
#include "stages/shade.h"

#if WF_HAS_BSDF_LAYERED && defined(WF_LANE_WIDTH) && WF_LANE_WIDTH > 1 && defined(WF_LOCAL_SIZE)
#define WF_GROUP_LANES 1

/* Emissive triangles the only lights, and none textured, coated (a clear
 * coat weighs the emission beneath) or
 * alpha-masked: lights/light_lanes.inc samples them in lanes. */
#define WF_LIGHTS_IN_LANES                                                                          \
    (WF_HAS_EMISSIVE_TRIANGLES && !WF_HAS_PUNCTUAL_LIGHTS && !WF_HAS_ENVIRONMENT && !WF_HAS_TEXTURES && \
     !WF_HAS_ALPHA_MASK && !WF_HAS_CLEARCOAT)

/* No textures, normal maps, vertex colours or first-hit AOVs, and no
 * material with a coat or sheen, and no placements to map a surface to the
 * world: a hit's surface is its triangle's corners and normals and its
 * material's factors, and the lanes find it too (stages/surface.inc). */
#define WF_SURFACE_IN_LANES                                                                  \
    (!WF_HAS_TEXTURES && !WF_HAS_NORMAL_MAPS && !WF_HAS_VERTEX_COLORS && !WF_HAS_AOVS && \
     !WF_HAS_CLEARCOAT && !WF_HAS_SHEEN && !WF_HAS_INSTANCES)

#define WF_W WF_LANE_WIDTH
#include "lanes/lane_width.inc"
#include "lights/light_lanes.inc"
#include "stages/scatter.inc"
#include "stages/surface.inc"
#include "common/rng_lanes.inc"
#include "common/sobol_lanes.inc"
/* WF_W stays WF_LANE_WIDTH to the end of the file: the code below speaks its vocabulary. */

/* Room for a whole work-group, in whole runs of lanes. */
#define WF_LANE_CAPACITY ((WF_LOCAL_SIZE + WF_LANE_WIDTH - 1) / WF_LANE_WIDTH * WF_LANE_WIDTH)

/* The fields of the structure of arrays, each WF_LANE_CAPACITY floats: the
 * BSDF query (the kind's parameters, WF_LANE_PARAM_<name>, one field or
 * three, none for a feature the program lacks: bsdf/kinds/layered.inc's
 * list), the scatter's surface and the light sample's numbers or the sample,
 * then what the lanes give back. A field of three holds x, y, z (or r, g, b)
 * in turn; masks and the light's segment end are held as floats. */
#define WF_LANE_PARAM_REAL(name, has) WF_LANE_PARAM_##name, WF_LANE_PARAM_##name##_last = WF_LANE_PARAM_##name + (has) - 1,
#define WF_LANE_PARAM_RGB(name, has) WF_LANE_PARAM_##name, WF_LANE_PARAM_##name##_last = WF_LANE_PARAM_##name + 3 * (has) - 1,
enum LaneField {
    WF_LAYERED_PARAMS(WF_LANE_PARAM_REAL, WF_LANE_PARAM_RGB)
    WF_LANE_WO, WF_LANE_WI_LIGHT = WF_LANE_WO + 3,
    WF_LANE_U = WF_LANE_WI_LIGHT + 3, WF_LANE_POSITION = WF_LANE_U + 3, WF_LANE_POSITION_ERROR = WF_LANE_POSITION + 3,
    WF_LANE_GEOMETRIC_NORMAL = WF_LANE_POSITION_ERROR + 3, WF_LANE_FRAME_X = WF_LANE_GEOMETRIC_NORMAL + 3,
    WF_LANE_FRAME_Y = WF_LANE_FRAME_X + 3, WF_LANE_FRAME_Z = WF_LANE_FRAME_Y + 3,
    WF_LANE_THROUGHPUT = WF_LANE_FRAME_Z + 3, WF_LANE_LIGHT = WF_LANE_THROUGHPUT + 3, WF_LANE_LIGHT_U,
    WF_LANE_LIGHT_WI = WF_LANE_LIGHT_U + 4, /* the light's numbers (WF_LIGHTS_IN_LANES), else its sample: */
    WF_LANE_LIGHT_RADIANCE = WF_LANE_LIGHT_WI + 3, WF_LANE_LIGHT_PDF = WF_LANE_LIGHT_RADIANCE + 3,
    WF_LANE_LIGHT_DELTA, WF_LANE_LIGHT_SEGMENT_END, WF_LANE_LIGHT_POINT,
    WF_LANE_LIGHT_POINT_ERROR = WF_LANE_LIGHT_POINT + 3, WF_LANE_LIGHT_NORMAL = WF_LANE_LIGHT_POINT_ERROR + 3,
    WF_LANE_TRIANGLE = WF_LANE_LIGHT_NORMAL + 3, /* the arrival (WF_SURFACE_IN_LANES): a bit pattern, */
    WF_LANE_HIT, /* t, b1, b2 */
    WF_LANE_DIRECTION = WF_LANE_HIT + 3, WF_LANE_PDF_PREVIOUS = WF_LANE_DIRECTION + 3, WF_LANE_GOES_ON,
    WF_LANE_PIXEL, WF_LANE_SAMPLE, WF_LANE_DEPTH, /* bit patterns, the numbers' keys (put either way) */
    WF_LANE_INPUTS, /* the inputs above, the surface's emission and the scatter below */
    WF_LANE_EMITS = WF_LANE_INPUTS, WF_LANE_EMITTED,
    WF_LANE_SHADOW = WF_LANE_EMITTED + 3, WF_LANE_SHADOW_ORIGIN, WF_LANE_SHADOW_SEGMENT = WF_LANE_SHADOW_ORIGIN + 3,
    WF_LANE_SHADOW_LIGHT = WF_LANE_SHADOW_SEGMENT + 3, WF_LANE_CONTINUES = WF_LANE_SHADOW_LIGHT + 3,
    WF_LANE_NEXT_THROUGHPUT, WF_LANE_RAY_ORIGIN = WF_LANE_NEXT_THROUGHPUT + 3,
    WF_LANE_RAY_DIRECTION = WF_LANE_RAY_ORIGIN + 3, WF_LANE_RAY_PDF = WF_LANE_RAY_DIRECTION + 3,
    WF_LANE_ROULETTE_U, /* not the lanes' input: drawn by shade_lanes_numbers for shade_lanes_get */
    WF_LANE_FIELDS
};
#undef WF_LANE_PARAM_REAL
#undef WF_LANE_PARAM_RGB

#define WF_LANE_AT(soa, field, at) (soa)[(field) * WF_LANE_CAPACITY + (at)]

WF_GPU_INLINE void lanes_put3(__local float* soa, uint field, uint at, float3 v) {
    WF_LANE_AT(soa, field, at) = v.x;
    WF_LANE_AT(soa, field + 1, at) = v.y;
    WF_LANE_AT(soa, field + 2, at) = v.z;
}

WF_GPU_INLINE float3 lanes_get3(__local const float* soa, uint field, uint at) {
    return (float3)(WF_LANE_AT(soa, field, at), WF_LANE_AT(soa, field + 1, at), WF_LANE_AT(soa, field + 2, at));
}

/* A light sample (shade_light's), for the lanes that do not take their own. */
WF_GPU_INLINE void lanes_put_light(__local float* soa, uint at, const LightSample* light) {
    lanes_put3(soa, WF_LANE_LIGHT_WI, at, light->wi);
    lanes_put3(soa, WF_LANE_LIGHT_RADIANCE, at, light->radiance);
    WF_LANE_AT(soa, WF_LANE_LIGHT_PDF, at) = light->pdf;
    WF_LANE_AT(soa, WF_LANE_LIGHT_DELTA, at) = light->delta ? 1.0f : 0.0f;
    WF_LANE_AT(soa, WF_LANE_LIGHT_SEGMENT_END, at) = (float)light->segment_end;
    lanes_put3(soa, WF_LANE_LIGHT_POINT, at, light->point);
    lanes_put3(soa, WF_LANE_LIGHT_POINT_ERROR, at, light->point_error);
    lanes_put3(soa, WF_LANE_LIGHT_NORMAL, at, light->normal);
}

/* A path as shade_surface left it, with its light sample where the lanes
 * take none; the lanes draw its BSDF numbers from its arrival's keys. */
WF_GPU_INLINE void shade_lanes_put(__local float* soa, uint at, const ShadeContext* c, const Arrival* a) {
    const BsdfQuery* q = &c->query;
#define WF_PUT_REAL(name, has) \
    if (has) WF_LANE_AT(soa, WF_LANE_PARAM_##name, at) = q->params.name;
#define WF_PUT_RGB(name, has) \
    if (has) lanes_put3(soa, WF_LANE_PARAM_##name, at, q->params.name);
    WF_LAYERED_PARAMS(WF_PUT_REAL, WF_PUT_RGB)
#undef WF_PUT_REAL
#undef WF_PUT_RGB
    lanes_put3(soa, WF_LANE_WO, at, q->wo);
    lanes_put3(soa, WF_LANE_POSITION, at, c->position);
    lanes_put3(soa, WF_LANE_POSITION_ERROR, at, c->position_error);
    lanes_put3(soa, WF_LANE_GEOMETRIC_NORMAL, at, c->geometric_normal);
    lanes_put3(soa, WF_LANE_FRAME_X, at, c->frame.x);
    lanes_put3(soa, WF_LANE_FRAME_Y, at, c->frame.y);
    lanes_put3(soa, WF_LANE_FRAME_Z, at, c->frame.z);
    lanes_put3(soa, WF_LANE_THROUGHPUT, at, c->throughput);
    WF_LANE_AT(soa, WF_LANE_PIXEL, at) = as_float(a->pixel);
    WF_LANE_AT(soa, WF_LANE_SAMPLE, at) = as_float(a->sample);
    WF_LANE_AT(soa, WF_LANE_DEPTH, at) = as_float(a->depth);
    WF_LANE_AT(soa, WF_LANE_LIGHT, at) = q->light ? 1.0f : 0.0f;
#if WF_LIGHTS_IN_LANES
    const float4 u = q->light ? c->light_u : (float4)(0.0f); /* any numbers serve a path without a light sample */
    WF_LANE_AT(soa, WF_LANE_LIGHT_U, at) = u.x;
    WF_LANE_AT(soa, WF_LANE_LIGHT_U + 1, at) = u.y;
    WF_LANE_AT(soa, WF_LANE_LIGHT_U + 2, at) = u.z;
    WF_LANE_AT(soa, WF_LANE_LIGHT_U + 3, at) = u.w;
#else
    lanes_put3(soa, WF_LANE_WI_LIGHT, at, q->wi_light);
    lanes_put_light(soa, at, &c->light);
#endif
}

#if WF_SURFACE_IN_LANES
/* A path that hit, as path_arrival found it: the lanes draw its numbers
 * (shade_lanes_numbers) and find its surface. */
WF_GPU_INLINE void shade_lanes_put_arrival(__local float* soa, uint at, const Arrival* a) {
    WF_LANE_AT(soa, WF_LANE_TRIANGLE, at) = as_float(a->triangle);
    WF_LANE_AT(soa, WF_LANE_HIT, at) = a->t;
    WF_LANE_AT(soa, WF_LANE_HIT + 1, at) = a->b1;
    WF_LANE_AT(soa, WF_LANE_HIT + 2, at) = a->b2;
    lanes_put3(soa, WF_LANE_DIRECTION, at, a->direction);
    WF_LANE_AT(soa, WF_LANE_PDF_PREVIOUS, at) = a->pdf_previous;
    lanes_put3(soa, WF_LANE_THROUGHPUT, at, a->throughput);
    WF_LANE_AT(soa, WF_LANE_GOES_ON, at) = a->goes_on ? 1.0f : 0.0f;
    WF_LANE_AT(soa, WF_LANE_PIXEL, at) = as_float(a->pixel);
    WF_LANE_AT(soa, WF_LANE_SAMPLE, at) = as_float(a->sample);
    WF_LANE_AT(soa, WF_LANE_DEPTH, at) = as_float(a->depth);
}

/* The emission the lanes found for the path put at `at`, added to it as
 * shade_surface adds it; returns whether the path goes on (then its scatter
 * waits in the lanes: shade_lanes_get). */
WF_GPU_INLINE bool shade_lanes_emission(__local const float* soa, uint at, PathState* path, const RenderParams* params,
                                    const FilmBuffers* film, uint slot) {
    if (WF_LANE_AT(soa, WF_LANE_EMITS, at) != 0.0f)
        add_radiance(path, params, film, slot, as_uint(WF_LANE_AT(soa, WF_LANE_PIXEL, at)),
                     as_uint(WF_LANE_AT(soa, WF_LANE_DEPTH, at)), lanes_get3(soa, WF_LANE_EMITTED, at));
    return WF_LANE_AT(soa, WF_LANE_GOES_ON, at) != 0.0f;
}
#else
/* Where shade_surface added the emission, and put only paths that go on. */
WF_GPU_INLINE bool shade_lanes_emission(__local const float* soa, uint at, PathState* path, const RenderParams* params,
                                    const FilmBuffers* film, uint slot) {
    return true;
}
#endif

/* The scatter of the path put at `at`, as scatter_x1 gives it, its shadow
 * ray, and its roulette number. */
WF_GPU_INLINE Scatter_x1 shade_lanes_get(__local const float* soa, uint at, float* roulette_u, ShadowRay_x1* shadow_ray) {
    *roulette_u = WF_LANE_AT(soa, WF_LANE_ROULETTE_U, at);
    shadow_ray->origin = vec_from_float3(lanes_get3(soa, WF_LANE_SHADOW_ORIGIN, at));
    shadow_ray->segment = vec_from_float3(lanes_get3(soa, WF_LANE_SHADOW_SEGMENT, at));
    Scatter_x1 out;
    out.shadow = WF_LANE_AT(soa, WF_LANE_SHADOW, at) != 0.0f;
    out.shadow_light = rgb_from_float3(lanes_get3(soa, WF_LANE_SHADOW_LIGHT, at));
    out.continues = WF_LANE_AT(soa, WF_LANE_CONTINUES, at) != 0.0f;
    out.throughput = rgb_from_float3(lanes_get3(soa, WF_LANE_NEXT_THROUGHPUT, at));
    out.ray_origin = vec_from_float3(lanes_get3(soa, WF_LANE_RAY_ORIGIN, at));
    out.ray_direction = vec_from_float3(lanes_get3(soa, WF_LANE_RAY_DIRECTION, at));
    out.ray_pdf = WF_LANE_AT(soa, WF_LANE_RAY_PDF, at);
    return out;
}

#define WF_LANE_LOAD(field, first) WF_CAT(vload, WF_LANE_WIDTH)(0, &WF_LANE_AT(soa, field, first))
#define WF_LANE_STORE(x, field, first) WF_CAT(vstore, WF_LANE_WIDTH)((x), 0, &WF_LANE_AT(soa, field, first))
#define WF_LANE_LOAD_VEC(field, first) \
    LFN(vec)(WF_LANE_LOAD(field, first), WF_LANE_LOAD((field) + 1, first), WF_LANE_LOAD((field) + 2, first))
#define WF_LANE_LOAD_RGB(field, first) \
    LFN(rgb)(WF_LANE_LOAD(field, first), WF_LANE_LOAD((field) + 1, first), WF_LANE_LOAD((field) + 2, first))
#define WF_LANE_STORE_VEC(v, field, first)         \
    do {                                           \
        WF_LANE_STORE((v).x, (field), first);      \
        WF_LANE_STORE((v).y, (field) + 1, first);  \
        WF_LANE_STORE((v).z, (field) + 2, first);  \
    } while (0)
#define WF_LANE_STORE_RGB(c, field, first)         \
    do {                                           \
        WF_LANE_STORE((c).r, (field), first);      \
        WF_LANE_STORE((c).g, (field) + 1, first);  \
        WF_LANE_STORE((c).b, (field) + 2, first);  \
    } while (0)
#define WF_LANE_MASK(field, first) (WF_LANE_LOAD(field, first) != 0.0f)
#define WF_LANE_FROM_MASK(m) WF_CAT(convert_float, WF_LANE_WIDTH)(-(m)) /* -1 set: 1.0f */

/* The four numbers of a group for each lane's (pixel, sample, bounce), as
 * sample_values draws them a path at a time. */
WF_INLINE void LFN(lane_sample_values)(const RenderParams* params, LUINT pixel, LUINT sample, LUINT bounce,
                                       uint group, LREAL u[4]) {
    if (params->sampler == WF_SAMPLER_SOBOL)
        LFN(sobol_uniform4)(params->seed, pixel, sample, bounce, group, u);
    else
        LFN(rng_uniform4)(params->seed, pixel, sample, bounce, group, u);
}

/* arrival_numbers for the paths put at [first, first + WF_LANE_WIDTH): the
 * BSDF's group (its direction's numbers and roulette's) and, where `light`,
 * the light's, which are otherwise drawn a path at a time before the lanes
 * (arrival_light_numbers, for shade_light). A path that ends here, or one in
 * a scene without lights, ignores what it gets. */
WF_GPU_INLINE void shade_lanes_numbers(__local float* soa, uint first, const RenderParams* params, bool light) {
    const LUINT pixel = LASUINT(WF_LANE_LOAD(WF_LANE_PIXEL, first));
    const LUINT sample = LASUINT(WF_LANE_LOAD(WF_LANE_SAMPLE, first));
    const LUINT depth = LASUINT(WF_LANE_LOAD(WF_LANE_DEPTH, first));
    LREAL u[4];
    if (light) {
        LFN(lane_sample_values)(params, pixel, sample, depth, WF_RNG_LIGHT, u);
        for (int i = 0; i < 4; ++i) WF_LANE_STORE(u[i], WF_LANE_LIGHT_U + i, first);
    }
    LFN(lane_sample_values)(params, pixel, sample, depth, WF_RNG_BSDF, u);
    for (int i = 0; i < 3; ++i) WF_LANE_STORE(u[i], WF_LANE_U + i, first);
    WF_LANE_STORE(u[3], WF_LANE_ROULETTE_U, first);
}

#if WF_SURFACE_IN_LANES
/* shade_surface in lanes, for the arrivals put at [first, first + WF_LANE_WIDTH):
 * the point and its normals, the emission found (into the lanes' fields, for
 * shade_lanes_emission), the material's factors, the frame and wo (on the
 * side the ray arrived from, but a solid's, which keeps its front), and
 * whether the path takes a light sample (bsdf_is_delta's rule for this kind). */
WF_GPU_INLINE void shade_lanes_surface(__local float* soa, uint first, const RenderParams* params, const Scene* scene,
                                   LFN(LayeredParams) * p, LVEC* wo, LFN(ScatterSurface) * s, LINT* light) {
    const LINT triangle = LASINT(WF_LANE_LOAD(WF_LANE_TRIANGLE, first));
    const LREAL t = WF_LANE_LOAD(WF_LANE_HIT, first);
    const LVEC direction = WF_LANE_LOAD_VEC(WF_LANE_DIRECTION, first);
    const LFN(SurfaceGeometry) g = LFN(surface_geometry)(scene, triangle, WF_LANE_LOAD(WF_LANE_HIT + 1, first),
                                                         WF_LANE_LOAD(WF_LANE_HIT + 2, first), direction);
    const LINT block_at = triangle / WF_BLOCK_LANES * WF_WORDS(TriangleBlock) + triangle % WF_BLOCK_LANES;
    const LINT material_at = LGATHERI((__global const int*)scene->triangles->material, block_at) * WF_WORDS(Material);
    __global const Material* m = scene->materials;
    s->throughput = WF_LANE_LOAD_RGB(WF_LANE_THROUGHPUT, first);

    /* Emission seen along the ray. */
    const LINT light_entry = LGATHERI(scene->triangles->light, block_at);
    const LINT flags = LGATHERI((__global const int*)&m->flags, material_at);
    const LINT emits = (light_entry >= 0) & (g.front_face | ((flags & (int)WF_MATERIAL_DOUBLE_SIDED) != 0));
    LRGB emitted = LFN(gray)(0.0f);
    if (LANY(emits)) { /* then the light table has an entry 0 */
        const LREAL pmf = LGATHER(&scene->lights->pmf, max(light_entry, 0) * WF_WORDS(LightEntry));
        const LREAL cos_light = -LFN(vec_dot)(g.geometric_normal, direction);
        const LREAL pdf_light = LFN(light_pdf_solid_angle)(pmf, g.area, t * t, cos_light);
        const LREAL weight =
            LFN(emission_weight)(params->light_sampling, WF_LANE_LOAD(WF_LANE_PDF_PREVIOUS, first), pdf_light);
        const LRGB emission = LFN(rgb)(LGATHER(m->emission, material_at), LGATHER(m->emission + 1, material_at),
                                       LGATHER(m->emission + 2, material_at));
        emitted = LFN(rgb_mul)(LFN(rgb_scale)(s->throughput, weight), emission);
    }
    WF_LANE_STORE(WF_LANE_FROM_MASK(emits), WF_LANE_EMITS, first);
    WF_LANE_STORE_RGB(emitted, WF_LANE_EMITTED, first);

    /* The material's factors: surface_bsdf's, no texture multiplying them. */
#define WF_GATHER_REAL(name, has) \
    if (has) p->name = LGATHER(&m->name, material_at);
#define WF_GATHER_RGB(name, has)                                                                        \
    if (has)                                                                                            \
        p->name = LFN(rgb)(LGATHER(m->name, material_at), LGATHER(m->name + 1, material_at), \
                           LGATHER(m->name + 2, material_at));
    WF_LAYERED_PARAMS(WF_GATHER_REAL, WF_GATHER_RGB)
#undef WF_GATHER_REAL
#undef WF_GATHER_RGB

    s->position = g.position;
    s->position_error = g.position_error;
    s->geometric_normal = g.geometric_normal;
    s->frame_z = LFN(facing)(g.normal, g.geometric_normal);
#if WF_HAS_TRANSMISSION
    /* A solid keeps its front side as +z (shade_surface's rule): wo.z < 0 from inside. */
    const LINT flip = LFN(layered_solid)(p) && !g.front_face;
    s->frame_z = LFN(vec_sel)(flip, LFN(vec_scale)(s->frame_z, -1.0f), s->frame_z);
    s->geometric_normal = LFN(vec_sel)(flip, LFN(vec_scale)(s->geometric_normal, -1.0f), s->geometric_normal);
#endif
    LFN(orthonormal_basis)(s->frame_z, &s->frame_x, &s->frame_y);
    *wo = LFN(vec_in_frame)(LFN(vec_scale)(direction, -1.0f), s->frame_x, s->frame_y, s->frame_z);

    /* bsdf_is_delta: a smooth interface over no diffuse albedo. */
    const LRGB albedo = LFN(rgb_scale)(p->base_color, LFN(layered_layer_share)(p));
    const LREAL albedo_sum = albedo.r + albedo.g + albedo.b;
    const LINT delta = LFN(layered_smooth)(p) & !(albedo_sum > 0.0f);
    *light = WF_LANE_MASK(WF_LANE_GOES_ON, first) & !delta & LMASK(params->light_count > 0u);
}
#endif

/* Shades the paths put at [first, first + WF_LANE_WIDTH) of `length`: their
 * surface where the lanes take it, their light sample where the lanes take
 * it, the BSDF core and the scatter. A run that ends past the last path first
 * repeats its first path's inputs into the empty lanes, so that no lane reads
 * what nobody wrote. */
WF_GPU_INLINE void shade_lanes_run(__local float* soa, uint first, uint length, const RenderParams* params,
                               const Scene* scene) {
    for (uint at = length; at < first + WF_LANE_WIDTH; ++at)
        for (uint f = 0; f < WF_LANE_INPUTS; ++f) WF_LANE_AT(soa, f, at) = WF_LANE_AT(soa, f, first);
    LFN(LayeredParams) p;
    LVEC wo;
    LFN(ScatterSurface) s;
    LFN(ScatterLight) l;
#if WF_GLASS_TABLE_IN_SCENE
    p.glass_table = scene->glass_albedo; /* a GPU's program with lanes (--kernels gpu --lane-width 8) */
#endif
#if WF_SURFACE_IN_LANES
    shade_lanes_numbers(soa, first, params, true);
    shade_lanes_surface(soa, first, params, scene, &p, &wo, &s, &l.present);
#else
#define WF_LOAD_REAL(name, has) \
    if (has) p.name = WF_LANE_LOAD(WF_LANE_PARAM_##name, first);
#define WF_LOAD_RGB(name, has) \
    if (has) p.name = WF_LANE_LOAD_RGB(WF_LANE_PARAM_##name, first);
    WF_LAYERED_PARAMS(WF_LOAD_REAL, WF_LOAD_RGB)
#undef WF_LOAD_REAL
#undef WF_LOAD_RGB
    shade_lanes_numbers(soa, first, params, false);
    wo = WF_LANE_LOAD_VEC(WF_LANE_WO, first);
    s.position = WF_LANE_LOAD_VEC(WF_LANE_POSITION, first);
    s.position_error = WF_LANE_LOAD_VEC(WF_LANE_POSITION_ERROR, first);
    s.geometric_normal = WF_LANE_LOAD_VEC(WF_LANE_GEOMETRIC_NORMAL, first);
    s.frame_x = WF_LANE_LOAD_VEC(WF_LANE_FRAME_X, first);
    s.frame_y = WF_LANE_LOAD_VEC(WF_LANE_FRAME_Y, first);
    s.frame_z = WF_LANE_LOAD_VEC(WF_LANE_FRAME_Z, first);
    s.throughput = WF_LANE_LOAD_RGB(WF_LANE_THROUGHPUT, first);
    l.present = WF_LANE_MASK(WF_LANE_LIGHT, first);
#endif
    const LVEC u = WF_LANE_LOAD_VEC(WF_LANE_U, first);
#if WF_LIGHTS_IN_LANES
    /* shade_light's sample and direction, in lanes. */
    const LREAL u_index = WF_LANE_LOAD(WF_LANE_LIGHT_U, first);
    const LREAL u_alias = WF_LANE_LOAD(WF_LANE_LIGHT_U + 3, first);
    const LINT entry = LFN(choose_light)(scene->lights, params->light_count, u_index, u_alias);
    l.sample = LFN(sample_emissive_triangle)(scene, entry, s.position, WF_LANE_LOAD(WF_LANE_LIGHT_U + 1, first),
                                             WF_LANE_LOAD(WF_LANE_LIGHT_U + 2, first));
    const LVEC wi_light = LFN(vec_in_frame)(l.sample.wi, s.frame_x, s.frame_y, s.frame_z);
#else
#if WF_SURFACE_IN_LANES
    /* shade_light, a lane at a time, from the points the lanes found. */
    WF_LANE_STORE_VEC(s.position, WF_LANE_POSITION, first);
    WF_LANE_STORE(WF_LANE_FROM_MASK(l.present), WF_LANE_LIGHT, first);
    for (uint at = first; at < first + WF_LANE_WIDTH; ++at) {
        LightSample light = no_light_sample();
        if (WF_LANE_AT(soa, WF_LANE_LIGHT, at) != 0.0f) {
            const float4 light_u =
                (float4)(WF_LANE_AT(soa, WF_LANE_LIGHT_U, at), WF_LANE_AT(soa, WF_LANE_LIGHT_U + 1, at),
                         WF_LANE_AT(soa, WF_LANE_LIGHT_U + 2, at), WF_LANE_AT(soa, WF_LANE_LIGHT_U + 3, at));
            light = sample_light(params, scene, lanes_get3(soa, WF_LANE_POSITION, at), light_u);
        }
        lanes_put_light(soa, at, &light);
    }
#endif
    l.sample.wi = WF_LANE_LOAD_VEC(WF_LANE_LIGHT_WI, first);
    l.sample.radiance = WF_LANE_LOAD_RGB(WF_LANE_LIGHT_RADIANCE, first);
    l.sample.pdf = WF_LANE_LOAD(WF_LANE_LIGHT_PDF, first);
    l.sample.delta = WF_LANE_MASK(WF_LANE_LIGHT_DELTA, first);
    l.sample.segment_end = LTOINT(WF_LANE_LOAD(WF_LANE_LIGHT_SEGMENT_END, first));
    l.sample.point = WF_LANE_LOAD_VEC(WF_LANE_LIGHT_POINT, first);
    l.sample.point_error = WF_LANE_LOAD_VEC(WF_LANE_LIGHT_POINT_ERROR, first);
    l.sample.normal = WF_LANE_LOAD_VEC(WF_LANE_LIGHT_NORMAL, first);
#if WF_SURFACE_IN_LANES
    /* shade_light's direction in the frame; a path without a sample ignores it. */
    const LVEC wi_light = LFN(vec_in_frame)(l.sample.wi, s.frame_x, s.frame_y, s.frame_z);
#else
    const LVEC wi_light = WF_LANE_LOAD_VEC(WF_LANE_WI_LIGHT, first);
#endif
#endif
    l.wi_local_z = wi_light.z;

    const LFN(LayeredAtWo) at = LFN(layered_at_wo)(&p, wo);
    LFN(ScatterAnswer) a;
    a.f_light = LFN(layered_eval_pdf)(&p, &at, wo, wi_light, params->hemisphere, &a.pdf_light);
    a.f = LFN(layered_sample)(&p, &at, wo, u, params->hemisphere, &a.wi, &a.pdf, &a.delta);

    const LFN(ShadowRay) shadow_ray = LFN(shadow_ray)(&s, &l.sample, 2.0f * params->scene_diameter);
    const LFN(Scatter) out = LFN(scatter)(&s, &l, &a, params->light_sampling);
    WF_LANE_STORE(WF_LANE_FROM_MASK(out.shadow), WF_LANE_SHADOW, first);
    WF_LANE_STORE_VEC(shadow_ray.origin, WF_LANE_SHADOW_ORIGIN, first);
    WF_LANE_STORE_VEC(shadow_ray.segment, WF_LANE_SHADOW_SEGMENT, first);
    WF_LANE_STORE_RGB(out.shadow_light, WF_LANE_SHADOW_LIGHT, first);
    WF_LANE_STORE(WF_LANE_FROM_MASK(out.continues), WF_LANE_CONTINUES, first);
    WF_LANE_STORE_RGB(out.throughput, WF_LANE_NEXT_THROUGHPUT, first);
    WF_LANE_STORE_VEC(out.ray_origin, WF_LANE_RAY_ORIGIN, first);
    WF_LANE_STORE_VEC(out.ray_direction, WF_LANE_RAY_DIRECTION, first);
    WF_LANE_STORE(out.ray_pdf, WF_LANE_RAY_PDF, first);
}

#undef WF_W
#endif
#endif
