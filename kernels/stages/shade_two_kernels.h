/* shade_two_kernels.h — shade as two kernels over the extension queue, where
 * the wavefront's global-queue schedules run it so (WF_SHADE_IN_TWO;
 * include/wavefront/shade_record.h says when and why): shade_surface_path
 * runs shade_path's steps up to the surface (the arrival, the emission it
 * finds, the BSDF's parameters) and leaves the
 * ShadeContext in the slot's record; shade_bsdf_path reads it back and runs
 * the rest (the light sample, its shadow ray, the BSDF core, the scatter).
 * The same steps on the same values, through memory that keeps every bit:
 * the two kernels make shade_path's image (tests/integrator/test_determinism.cpp
 * runs them with a CPU's kernels against the megakernel, tests/device/
 * test_specialize.cpp a GPU's against a CPU's). The flags ride as a bit
 * pattern, a denormal as a float, which loads and stores move unchanged (only
 * arithmetic may flush it; none touches it): as a whole number converted,
 * they took gfx90a's shade two VGPRs more. Device only. */
#ifndef WF_STAGE_SHADE_TWO_KERNELS_H
#define WF_STAGE_SHADE_TWO_KERNELS_H

#include "wavefront/shade_record.h"
#include "stages/shade.h"

WF_INLINE __global float4* shade_row(__global float4* records, uint pool_size, enum ShadeRecordRow row, uint slot) {
    return records + (size_t)row * pool_size + slot;
}

/* The first kernel's step: returns whether the path goes on to the second
 * (otherwise it ended at its arrival, and the second sends it to be
 * accumulated). */
WF_GPU_INLINE bool shade_surface_path(PathState* path, const RenderParams* params, uint slot, const Scene* scene,
                                      const FilmBuffers* film, __global float4* records) {
    const uint n = params->pool_size;
    Arrival arrival;
    ShadeContext c;
    if (!shade_arrival(path, params, slot, scene, film, &arrival) ||
        !shade_surface(path, params, slot, scene, film, &arrival, &c)) {
        *shade_row(records, n, WF_SHADE_ROW_wo, slot) = (float4)(0.0f);
        return false;
    }
    const BsdfParams* b = &c.query.params;
    const uint flags = WF_SHADE_RECORD_GOES_ON | (c.query.light ? WF_SHADE_RECORD_LIGHT : 0u);
    *shade_row(records, n, WF_SHADE_ROW_base_color, slot) = (float4)(b->base_color, b->metallic);
    *shade_row(records, n, WF_SHADE_ROW_specular, slot) = (float4)(b->specular_color, b->specular);
    *shade_row(records, n, WF_SHADE_ROW_interface, slot) =
        (float4)(b->roughness, b->ior, b->transmission, b->thin_walled ? 1.0f : 0.0f);
    if (WF_HAS_SHEEN) *shade_row(records, n, WF_SHADE_ROW_sheen, slot) = (float4)(b->sheen_color, b->sheen_roughness);
    *shade_row(records, n, WF_SHADE_ROW_wo, slot) = (float4)(c.query.wo, as_float(flags));
    *shade_row(records, n, WF_SHADE_ROW_u, slot) = (float4)(c.query.u, c.roulette_u);
    if (c.query.light) *shade_row(records, n, WF_SHADE_ROW_light_u, slot) = c.light_u;
    *shade_row(records, n, WF_SHADE_ROW_position, slot) = (float4)(c.position, b->clearcoat);
    *shade_row(records, n, WF_SHADE_ROW_position_error, slot) = (float4)(c.position_error, b->clearcoat_roughness);
    *shade_row(records, n, WF_SHADE_ROW_geometric_normal, slot) = (float4)(c.geometric_normal, 0.0f);
    *shade_row(records, n, WF_SHADE_ROW_frame_z, slot) = (float4)(c.frame.z, 0.0f);
    return true;
}

/* What the scatter needs of the surface: the point, its frame (x and y found
 * again from z, as shade_surface found them) and the path's throughput. */
WF_INLINE void load_shade_surface(const PathState* path, uint slot, __global float4* rows, uint n, ShadeContext* c) {
    c->position = shade_row(rows, n, WF_SHADE_ROW_position, slot)->xyz;
    c->position_error = shade_row(rows, n, WF_SHADE_ROW_position_error, slot)->xyz;
    c->geometric_normal = shade_row(rows, n, WF_SHADE_ROW_geometric_normal, slot)->xyz;
    c->frame.z = shade_row(rows, n, WF_SHADE_ROW_frame_z, slot)->xyz;
    lvec1 frame_x, frame_y;
    orthonormal_basis_x1(vec_from_float3(c->frame.z), &frame_x, &frame_y);
    c->frame.x = vec_to_float3(frame_x);
    c->frame.y = vec_to_float3(frame_y);
    c->throughput = path->throughput[slot].xyz; /* which the surface kernel leaves as it was */
}

/* The BSDF's query, the numbers and the light's, as the surface kernel left them. */
WF_INLINE void load_shade_query(const RenderParams* params, const Scene* scene, uint slot, __global float4* rows,
                                uint n, uint flags, ShadeContext* c) {
    BsdfQuery* q = &c->query;
    BsdfParams* b = &q->params;
    const float4 base_color = *shade_row(rows, n, WF_SHADE_ROW_base_color, slot);
    const float4 specular = *shade_row(rows, n, WF_SHADE_ROW_specular, slot);
    const float4 interface = *shade_row(rows, n, WF_SHADE_ROW_interface, slot);
    const float4 sheen = WF_HAS_SHEEN ? *shade_row(rows, n, WF_SHADE_ROW_sheen, slot) : (float4)(0.0f);
    const float4 wo = *shade_row(rows, n, WF_SHADE_ROW_wo, slot);
    const float4 u = *shade_row(rows, n, WF_SHADE_ROW_u, slot);
#if WF_GLASS_TABLE_IN_SCENE
    b->glass_table = scene->glass_albedo;
#endif
    b->base_color = base_color.xyz;
    b->metallic = base_color.w;
    b->specular_color = specular.xyz;
    b->specular = specular.w;
    b->roughness = interface.x;
    b->ior = interface.y;
    b->transmission = interface.z;
    b->thin_walled = interface.w != 0.0f;
    b->sheen_color = sheen.xyz;
    b->sheen_roughness = sheen.w;
    b->clearcoat = shade_row(rows, n, WF_SHADE_ROW_position, slot)->w;
    b->clearcoat_roughness = shade_row(rows, n, WF_SHADE_ROW_position_error, slot)->w;
    b->hemisphere = params->hemisphere;
    q->wo = wo.xyz;
    q->u = u.xyz;
    q->light = (flags & WF_SHADE_RECORD_LIGHT) != 0u;
    c->roulette_u = u.w;
    c->light_u = q->light ? *shade_row(rows, n, WF_SHADE_ROW_light_u, slot) : (float4)(0.0f);
}

/* The light sample as the scatter reads it (scatter_light_x1), and the BSDF
 * there: the direction, in the world and, found again as shade_light found
 * it (light_in_frame), in the frame; the radiance, pdf and kind; f and its pdf. */
WF_INLINE void store_scatter_light(__global float4* rows, uint n, uint slot, const LightSample* l) {
    *shade_row(rows, n, WF_SHADE_ROW_light_wi, slot) = (float4)(l->wi, l->delta ? 1.0f : 0.0f);
    *shade_row(rows, n, WF_SHADE_ROW_light_radiance, slot) = (float4)(l->radiance, l->pdf);
}

WF_INLINE void load_scatter_light(__global float4* rows, uint n, uint slot, ShadeContext* c, BsdfAnswer* a) {
    c->light = no_light_sample();
    c->query.wi_light = (float3)(0.0f, 0.0f, 1.0f);
    a->f_light = (float3)(0.0f);
    a->pdf_light = 0.0f;
    if (!c->query.light) return;
    const float4 wi = *shade_row(rows, n, WF_SHADE_ROW_light_wi, slot);
    const float4 radiance = *shade_row(rows, n, WF_SHADE_ROW_light_radiance, slot);
    const float4 f = *shade_row(rows, n, WF_SHADE_ROW_light_f, slot);
    c->light.wi = wi.xyz;
    c->light.delta = wi.w != 0.0f;
    c->light.radiance = radiance.xyz;
    c->light.pdf = radiance.w;
    c->query.wi_light = light_in_frame(c);
    a->f_light = f.xyz;
    a->pdf_light = f.w;
}

/* The second kernel's step: returns the queue the path goes to next. The
 * BSDF core runs in its two halves (bsdf/kinds.h), and what the scatter
 * needs is read again after the sample rather than held through it: on
 * gfx90a the Cornell box's one kernel took 120 VGPRs; this one 106 with the
 * light sample held through the core, 99 with it kept in the record, 94 with
 * the BSDF's value at it kept too (bench/results/gpu-isa.md). */
WF_GPU_INLINE uint shade_bsdf_path(PathState* path, const RenderParams* params, uint slot, const Scene* scene,
                                   __global float4* rows) {
    const uint n = params->pool_size;
    const uint flags = as_uint(shade_row(rows, n, WF_SHADE_ROW_wo, slot)->w);
    if (!(flags & WF_SHADE_RECORD_GOES_ON)) return WF_QUEUE_FINISHED;
    ShadeContext c;
    load_shade_surface(path, slot, rows, n, &c);
    load_shade_query(params, scene, slot, rows, n, flags, &c);
    shade_light(params, scene, &c);
    shade_shadow_ray(path, params, slot, &c);
    BsdfAnswer a;
    {
        const BsdfAtQuery at = bsdf_at_query(&c.query);
        if (c.query.light) {
            store_scatter_light(rows, n, slot, &c.light);
            float pdf;
            const float3 f = bsdf_light(&c.query, &at, &pdf);
            *shade_row(rows, n, WF_SHADE_ROW_light_f, slot) = (float4)(f, pdf);
        }
        a.sample = bsdf_sample_core(&c.query, &at);
    }
    load_shade_surface(path, slot, rows, n, &c);
    load_scatter_light(rows, n, slot, &c, &a);
    c.roulette_u = shade_row(rows, n, WF_SHADE_ROW_u, slot)->w;
    return shade_scatter(path, params, slot, &c, &a);
}

#endif
