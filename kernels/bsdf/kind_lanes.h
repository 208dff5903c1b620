/* kind_lanes.h — the lane path of the BSDF core, for the group schedule: a
 * work-group's queries of one kind gathered into a structure of arrays in
 * local memory (bsdf_lanes_put, one path a work-item), answered WF_LANE_WIDTH
 * at a time by the kind's code at that width (bsdf_lanes_answer, one
 * work-item a run of lanes), and read back (bsdf_lanes_get). Its answers are
 * the width-1 core's to the bit (tests/kernels/test_bsdf_kinds.cpp), so the
 * group schedule makes the megakernel's bytes. Device only. */
#ifndef WF_BSDF_KIND_LANES_H
#define WF_BSDF_KIND_LANES_H

#include "wavefront/compat.h"
#include "bsdf/kinds.h"

#if WF_HAS_BSDF_OPAQUE && defined(WF_LANE_WIDTH) && WF_LANE_WIDTH > 1 && defined(WF_LOCAL_SIZE)
#define WF_GROUP_LANES 1

/* Room for a whole work-group, in whole runs of lanes. */
#define WF_LANE_CAPACITY ((WF_LOCAL_SIZE + WF_LANE_WIDTH - 1) / WF_LANE_WIDTH * WF_LANE_WIDTH)

/* The fields of the structure of arrays, each WF_LANE_CAPACITY floats. */
enum LaneField {
    WF_LANE_BASE, WF_LANE_METALLIC = WF_LANE_BASE + 3, WF_LANE_ROUGHNESS, WF_LANE_SPECULAR, WF_LANE_SPECULAR_COLOR,
    WF_LANE_IOR = WF_LANE_SPECULAR_COLOR + 3, WF_LANE_WO, WF_LANE_WI_LIGHT = WF_LANE_WO + 3,
    WF_LANE_U = WF_LANE_WI_LIGHT + 3, /* the query above, the answer below */
    WF_LANE_F_LIGHT = WF_LANE_U + 3, WF_LANE_PDF_LIGHT = WF_LANE_F_LIGHT + 3, WF_LANE_WI, WF_LANE_F = WF_LANE_WI + 3,
    WF_LANE_PDF = WF_LANE_F + 3, WF_LANE_DELTA, WF_LANE_FIELDS
};

#define WF_LANE_AT(soa, field, at) (soa)[(field) * WF_LANE_CAPACITY + (at)]

WF_INLINE void lanes_put3(__local float* soa, uint field, uint at, float3 v) {
    WF_LANE_AT(soa, field, at) = v.x;
    WF_LANE_AT(soa, field + 1, at) = v.y;
    WF_LANE_AT(soa, field + 2, at) = v.z;
}

WF_INLINE float3 lanes_get3(__local const float* soa, uint field, uint at) {
    return (float3)(WF_LANE_AT(soa, field, at), WF_LANE_AT(soa, field + 1, at), WF_LANE_AT(soa, field + 2, at));
}

WF_INLINE void bsdf_lanes_put(__local float* soa, uint at, const BsdfQuery* q) {
    lanes_put3(soa, WF_LANE_BASE, at, q->params.base_color);
    WF_LANE_AT(soa, WF_LANE_METALLIC, at) = q->params.metallic;
    WF_LANE_AT(soa, WF_LANE_ROUGHNESS, at) = q->params.roughness;
    WF_LANE_AT(soa, WF_LANE_SPECULAR, at) = q->params.specular;
    lanes_put3(soa, WF_LANE_SPECULAR_COLOR, at, q->params.specular_color);
    WF_LANE_AT(soa, WF_LANE_IOR, at) = q->params.ior;
    lanes_put3(soa, WF_LANE_WO, at, q->wo);
    lanes_put3(soa, WF_LANE_WI_LIGHT, at, q->wi_light);
    lanes_put3(soa, WF_LANE_U, at, q->u);
}

WF_INLINE BsdfAnswer bsdf_lanes_get(__local const float* soa, uint at) {
    BsdfAnswer a;
    a.f_light = lanes_get3(soa, WF_LANE_F_LIGHT, at);
    a.pdf_light = WF_LANE_AT(soa, WF_LANE_PDF_LIGHT, at);
    a.sample.wi = lanes_get3(soa, WF_LANE_WI, at);
    a.sample.f = lanes_get3(soa, WF_LANE_F, at);
    a.sample.pdf = WF_LANE_AT(soa, WF_LANE_PDF, at);
    a.sample.delta = WF_LANE_AT(soa, WF_LANE_DELTA, at) != 0.0f;
    return a;
}

#define WF_LANE_REAL WF_CAT(lreal, WF_LANE_WIDTH)
#define WF_LANE_LOAD(field, first) WF_CAT(vload, WF_LANE_WIDTH)(0, &WF_LANE_AT(soa, field, first))
#define WF_LANE_STORE(x, field, first) WF_CAT(vstore, WF_LANE_WIDTH)((x), 0, &WF_LANE_AT(soa, field, first))
#define WF_LANE_X(name) WF_CAT(name, WF_CAT(_x, WF_LANE_WIDTH))

/* Answers the queries [first, first + WF_LANE_WIDTH) of `length`; a run that
 * ends past the queue first repeats its first query into the empty lanes, so
 * that no lane reads what nobody wrote. */
WF_INLINE void bsdf_lanes_answer(__local float* soa, uint first, uint length, uint hemisphere) {
    for (uint at = length; at < first + WF_LANE_WIDTH; ++at)
        for (uint f = 0; f < WF_LANE_F_LIGHT; ++f) WF_LANE_AT(soa, f, at) = WF_LANE_AT(soa, f, first);
    WF_LANE_X(OpaqueParams) p;
    p.base_color.r = WF_LANE_LOAD(WF_LANE_BASE, first);
    p.base_color.g = WF_LANE_LOAD(WF_LANE_BASE + 1, first);
    p.base_color.b = WF_LANE_LOAD(WF_LANE_BASE + 2, first);
    p.metallic = WF_LANE_LOAD(WF_LANE_METALLIC, first);
    p.roughness = WF_LANE_LOAD(WF_LANE_ROUGHNESS, first);
    p.specular = WF_LANE_LOAD(WF_LANE_SPECULAR, first);
    p.specular_color.r = WF_LANE_LOAD(WF_LANE_SPECULAR_COLOR, first);
    p.specular_color.g = WF_LANE_LOAD(WF_LANE_SPECULAR_COLOR + 1, first);
    p.specular_color.b = WF_LANE_LOAD(WF_LANE_SPECULAR_COLOR + 2, first);
    p.ior = WF_LANE_LOAD(WF_LANE_IOR, first);
    WF_CAT(lvec, WF_LANE_WIDTH) wo, wi_light, u, wi;
    wo.x = WF_LANE_LOAD(WF_LANE_WO, first), wo.y = WF_LANE_LOAD(WF_LANE_WO + 1, first);
    wo.z = WF_LANE_LOAD(WF_LANE_WO + 2, first);
    wi_light.x = WF_LANE_LOAD(WF_LANE_WI_LIGHT, first), wi_light.y = WF_LANE_LOAD(WF_LANE_WI_LIGHT + 1, first);
    wi_light.z = WF_LANE_LOAD(WF_LANE_WI_LIGHT + 2, first);
    u.x = WF_LANE_LOAD(WF_LANE_U, first), u.y = WF_LANE_LOAD(WF_LANE_U + 1, first);
    u.z = WF_LANE_LOAD(WF_LANE_U + 2, first);
    const WF_LANE_X(OpaqueAtWo) at = WF_LANE_X(opaque_at_wo)(&p, wo);
    WF_LANE_REAL pdf_light, pdf;
    WF_CAT(lint, WF_LANE_WIDTH) delta;
    const WF_CAT(lrgb, WF_LANE_WIDTH) f_light = WF_LANE_X(opaque_eval_pdf)(&p, &at, wo, wi_light, hemisphere, &pdf_light);
    const WF_CAT(lrgb, WF_LANE_WIDTH) f = WF_LANE_X(opaque_sample)(&p, &at, wo, u, hemisphere, &wi, &pdf, &delta);
    WF_LANE_STORE(f_light.r, WF_LANE_F_LIGHT, first);
    WF_LANE_STORE(f_light.g, WF_LANE_F_LIGHT + 1, first);
    WF_LANE_STORE(f_light.b, WF_LANE_F_LIGHT + 2, first);
    WF_LANE_STORE(pdf_light, WF_LANE_PDF_LIGHT, first);
    WF_LANE_STORE(wi.x, WF_LANE_WI, first);
    WF_LANE_STORE(wi.y, WF_LANE_WI + 1, first);
    WF_LANE_STORE(wi.z, WF_LANE_WI + 2, first);
    WF_LANE_STORE(f.r, WF_LANE_F, first);
    WF_LANE_STORE(f.g, WF_LANE_F + 1, first);
    WF_LANE_STORE(f.b, WF_LANE_F + 2, first);
    WF_LANE_STORE(pdf, WF_LANE_PDF, first);
    WF_LANE_STORE(WF_CAT(convert_float, WF_LANE_WIDTH)(-delta), WF_LANE_DELTA, first);
}

#endif
#endif
