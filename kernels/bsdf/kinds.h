/* kinds.h — the BSDF kinds (include/wavefront/bsdf_kinds.h) a program holds:
 * each written once in the lane vocabulary (lanes/lanes.h) and expanded here at
 * width 1, and at WF_LANE_WIDTH where the group schedule shades in lanes; and
 * the BSDF core of one path at width 1: what the shade stage calls between
 * the surface and the scatter (stages/shade.h). The general BSDF
 * (bsdf/bsdf.h) is the oracle the kinds are tested against
 * (bsdf/kind_probe.cl). */
#ifndef WF_BSDF_KINDS_H
#define WF_BSDF_KINDS_H

#include "wavefront/compat.h"
#include "compiled_features.h"
#include "wavefront/bsdf_kinds.h"
#include "bsdf/bsdf.h"
#include "lanes/lanes.h"

#if WF_HAS_BSDF_LAYERED
#define WF_W 1
#include "lanes/lane_width.inc"
#include "bsdf/kinds/layered.inc"
#undef WF_W
/* The group schedule's lanes: the host sets WF_LANE_WIDTH (8 on CPUs of
 * 8-float vectors or wider, or --lane-width). */
#if defined(WF_LANE_WIDTH) && WF_LANE_WIDTH > 1
#define WF_W WF_LANE_WIDTH
#include "lanes/lane_width.inc"
#include "bsdf/kinds/layered.inc"
#undef WF_W
#endif
#endif

/* What the BSDF core takes at one shading point and gives back: the BSDF at
 * the light sample's direction, and a sampled continuation. */
typedef struct BsdfQuery {
    BsdfParams params;
    float3 wo, wi_light; /* local frame */
    float3 u;            /* BSDF sampling's three numbers */
    bool light;          /* there is a light sample to evaluate (width 1 skips it otherwise) */
} BsdfQuery;

typedef struct BsdfAnswer {
    float3 f_light; /* at wi_light, without the cosine */
    float pdf_light;
    BsdfSample sample;
} BsdfAnswer;

#if WF_HAS_BSDF_LAYERED
#define WF_COPY_REAL(name, has) p.name = b->name;
#define WF_COPY_RGB(name, has) p.name = rgb_from_float3(b->name);
WF_INLINE LayeredParams_x1 layered_params_x1(const BsdfParams* b) {
    LayeredParams_x1 p;
    WF_LAYERED_PARAMS(WF_COPY_REAL, WF_COPY_RGB)
#if WF_GLASS_TABLE_IN_SCENE
    p.glass_table = b->glass_table;
#endif
    return p;
}
#undef WF_COPY_REAL
#undef WF_COPY_RGB

/* The core in two halves at width 1, for a kernel that keeps the first's
 * answer in memory while the second runs (stages/shade_two_kernels.h): what both
 * share at wo, the BSDF at the light sample's direction, then a sample.
 * layered_core_x1 is both, in this order. */
typedef struct LayeredAtQuery_x1 {
    LayeredParams_x1 p;
    lvec1 wo;
    LayeredAtWo_x1 at;
} LayeredAtQuery_x1;

WF_INLINE LayeredAtQuery_x1 layered_at_query_x1(const BsdfQuery* q) {
    LayeredAtQuery_x1 s;
    s.p = layered_params_x1(&q->params);
    s.wo = vec_from_float3(q->wo);
    s.at = layered_at_wo_x1(&s.p, s.wo);
    return s;
}

/* f at wi_light, without the cosine, and its pdf; the query has a light sample. */
WF_INLINE float3 layered_light_x1(const BsdfQuery* q, const LayeredAtQuery_x1* s, float* pdf) {
    return rgb_to_float3(
        layered_eval_pdf_x1(&s->p, &s->at, s->wo, vec_from_float3(q->wi_light), q->params.hemisphere, pdf));
}

WF_INLINE BsdfSample layered_sample_core_x1(const BsdfQuery* q, const LayeredAtQuery_x1* s) {
    BsdfSample sample;
    lvec1 wi;
    int delta;
    sample.f = rgb_to_float3(
        layered_sample_x1(&s->p, &s->at, s->wo, vec_from_float3(q->u), q->params.hemisphere, &wi, &sample.pdf, &delta));
    sample.wi = vec_to_float3(wi);
    sample.delta = delta;
    return sample;
}

WF_INLINE BsdfAnswer layered_core_x1(const BsdfQuery* q) {
    const LayeredAtQuery_x1 s = layered_at_query_x1(q);
    BsdfAnswer a;
    a.f_light = (float3)(0.0f);
    a.pdf_light = 0.0f;
    if (q->light) a.f_light = layered_light_x1(q, &s, &a.pdf_light);
    a.sample = layered_sample_core_x1(q, &s);
    return a;
}
#endif

/* The core at width 1: the kind's, every material's (wavefront/bsdf_kinds.h);
 * and its halves. */
WF_GPU_INLINE BsdfAnswer bsdf_core(const BsdfQuery* q) { return layered_core_x1(q); }
typedef LayeredAtQuery_x1 BsdfAtQuery;
WF_INLINE BsdfAtQuery bsdf_at_query(const BsdfQuery* q) { return layered_at_query_x1(q); }
WF_INLINE float3 bsdf_light(const BsdfQuery* q, const BsdfAtQuery* s, float* pdf) { return layered_light_x1(q, s, pdf); }
WF_INLINE BsdfSample bsdf_sample_core(const BsdfQuery* q, const BsdfAtQuery* s) { return layered_sample_core_x1(q, s); }

#endif
