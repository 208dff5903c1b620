/* kind_probe.cl — the BSDF core of every kind over arrays of queries, for
 * tests/kernels/test_bsdf_kinds.cpp (the kinds against the general BSDF, and
 * each width against width 1) and bench/bsdf_lanes.cpp (their rates). Built
 * with -DWF_LANE_WIDTH=8; width 16 is expanded here.
 *
 * The queries are a structure of arrays, n floats a field, in the order of
 * probe_query; the answers 12 floats an item (f at wi, its pdf, the sample's
 * wi, f, pdf and delta), item-major at width 1, field-major in lanes. */
#include "bsdf/kinds.h"
#define WF_W 16
#include "lanes/lane_width.inc"
#include "bsdf/kinds/layered.inc"
#undef WF_W

/* The queries' fields: the layered kind's parameters in the order of its
 * list (bsdf/kinds/layered.inc), a field each real and three each colour, then
 * wo, wi and u (tests/kernels/test_bsdf_kinds.cpp's Field). */
#define IN(field) in[(field) * n + i]
#define QUERY_REAL(name, has) \
    q.params.name = IN(field); \
    field += 1;
#define QUERY_RGB(name, has)                                              \
    q.params.name = (float3)(IN(field), IN(field + 1), IN(field + 2)); \
    field += 3;
WF_INLINE BsdfQuery probe_query(__global const float* in, uint n, uint i, uint hemisphere) {
    BsdfQuery q;
    uint field = 0;
    WF_LAYERED_PARAMS(QUERY_REAL, QUERY_RGB)
    q.params.hemisphere = hemisphere;
    q.wo = (float3)(IN(field), IN(field + 1), IN(field + 2));
    q.wi_light = (float3)(IN(field + 3), IN(field + 4), IN(field + 5));
    q.u = (float3)(IN(field + 6), IN(field + 7), IN(field + 8));
    q.light = true;
    return q;
}

/* The general BSDF, the kinds' oracle, answering the same query. */
WF_INLINE BsdfAnswer general_core(const BsdfQuery* q) {
    const BsdfAtWo at = bsdf_at_wo(&q->params, q->wo); /* once, for both techniques */
    BsdfAnswer a;
    a.f_light = (float3)(0.0f);
    a.pdf_light = 0.0f;
    if (q->light) a.f_light = bsdf_eval_pdf_at(&q->params, &at, q->wo, q->wi_light, &a.pdf_light);
    a.sample = bsdf_sample_at(&q->params, &at, q->wo, q->u);
    return a;
}

WF_INLINE void store_answer(__global float* o, BsdfAnswer a) {
    const float v[12] = {a.f_light.x, a.f_light.y, a.f_light.z, a.pdf_light, a.sample.wi.x, a.sample.wi.y,
                         a.sample.wi.z, a.sample.f.x, a.sample.f.y, a.sample.f.z, a.sample.pdf, (float)a.sample.delta};
    for (int k = 0; k < 12; ++k) o[k] = v[k];
}

__kernel void general_probe(__global const float* in, uint n, uint hemisphere, __global float* out) {
    const uint i = get_global_id(0);
    const BsdfQuery q = probe_query(in, n, i, hemisphere);
    store_answer(out + 12 * i, general_core(&q));
}

__kernel void layered_probe_x1(__global const float* in, uint n, uint hemisphere, __global float* out) {
    const uint i = get_global_id(0);
    const BsdfQuery q = probe_query(in, n, i, hemisphere);
    store_answer(out + 12 * i, layered_core_x1(&q));
}

/* WF_W items a work-item, from the same arrays, PROBE_W wide. */
#define PROBE_LOAD(f) WF_CAT(vload, PROBE_W)(i, in + (f) * n)
#define PROBE_REAL(name, has) \
    p.name = PROBE_LOAD(field); \
    field += 1;
#define PROBE_RGB(name, has)                \
    p.name.r = PROBE_LOAD(field);           \
    p.name.g = PROBE_LOAD(field + 1);       \
    p.name.b = PROBE_LOAD(field + 2);       \
    field += 3;
#define LANE_PROBE(W)                                                                                         \
    __kernel void layered_probe_x##W(__global const float* in, uint n, uint hemisphere, __global float* out) { \
        const uint i = get_global_id(0);                                                                      \
        LayeredParams_x##W p;                                                                                  \
        uint field = 0;                                                                                       \
        WF_LAYERED_PARAMS(PROBE_REAL, PROBE_RGB)                                                               \
        lvec##W wo, wi, u, sampled;                                                                           \
        wo.x = PROBE_LOAD(field), wo.y = PROBE_LOAD(field + 1), wo.z = PROBE_LOAD(field + 2);                 \
        wi.x = PROBE_LOAD(field + 3), wi.y = PROBE_LOAD(field + 4), wi.z = PROBE_LOAD(field + 5);             \
        u.x = PROBE_LOAD(field + 6), u.y = PROBE_LOAD(field + 7), u.z = PROBE_LOAD(field + 8);                \
        const LayeredAtWo_x##W at = layered_at_wo_x##W(&p, wo);                                                 \
        lreal##W pdf_light, pdf;                                                                              \
        lint##W delta;                                                                                        \
        const lrgb##W f_light = layered_eval_pdf_x##W(&p, &at, wo, wi, hemisphere, &pdf_light);                \
        const lrgb##W f = layered_sample_x##W(&p, &at, wo, u, hemisphere, &sampled, &pdf, &delta);             \
        const lreal##W v[12] = {f_light.r, f_light.g, f_light.b, pdf_light, sampled.x, sampled.y,            \
                                sampled.z, f.r, f.g, f.b, pdf, convert_float##W(-delta)};                    \
        for (int k = 0; k < 12; ++k) vstore##W(v[k], i, out + k * n); /* answer-major */                    \
    }
#define PROBE_W 8
LANE_PROBE(8)
#undef PROBE_W
#define PROBE_W 16
LANE_PROBE(16)
#undef PROBE_W
