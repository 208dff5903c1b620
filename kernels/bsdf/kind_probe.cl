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
#include "bsdf/kinds/opaque.inc"
#undef WF_W

#define IN(field) in[(field) * n + i]
WF_INLINE BsdfQuery probe_query(__global const float* in, uint n, uint i, uint hemisphere) {
    BsdfQuery q;
    q.params.base_color = (float3)(IN(0), IN(1), IN(2));
    q.params.metallic = IN(3);
    q.params.roughness = IN(4);
    q.params.transmission = 0.0f;
    q.params.ior = IN(9);
    q.params.specular = IN(5);
    q.params.specular_color = (float3)(IN(6), IN(7), IN(8));
    q.params.thin_walled = 0u;
    q.params.clearcoat = IN(19);
    q.params.clearcoat_roughness = IN(20);
    q.params.sheen_color = (float3)(IN(21), IN(22), IN(23));
    q.params.sheen_roughness = IN(24);
    q.params.hemisphere = hemisphere;
    q.wo = (float3)(IN(10), IN(11), IN(12));
    q.wi_light = (float3)(IN(13), IN(14), IN(15));
    q.u = (float3)(IN(16), IN(17), IN(18));
    q.light = true;
    return q;
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

__kernel void opaque_probe_x1(__global const float* in, uint n, uint hemisphere, __global float* out) {
    const uint i = get_global_id(0);
    const BsdfQuery q = probe_query(in, n, i, hemisphere);
    store_answer(out + 12 * i, opaque_core_x1(&q));
}

#if WF_HAS_CLEARCOAT
#define PROBE_COAT(W)                                  \
    p.clearcoat = vload##W(i, in + 19 * n);            \
    p.clearcoat_roughness = vload##W(i, in + 20 * n);
#else
#define PROBE_COAT(W)
#endif
#if WF_HAS_SHEEN
#define PROBE_SHEEN(W)                                 \
    p.sheen_color.r = vload##W(i, in + 21 * n);        \
    p.sheen_color.g = vload##W(i, in + 22 * n);        \
    p.sheen_color.b = vload##W(i, in + 23 * n);        \
    p.sheen_roughness = vload##W(i, in + 24 * n);
#else
#define PROBE_SHEEN(W)
#endif

/* WF_W items a work-item, from the same arrays. */
#define LANE_PROBE(W)                                                                                         \
    __kernel void opaque_probe_x##W(__global const float* in, uint n, uint hemisphere, __global float* out) { \
        const uint i = get_global_id(0);                                                                      \
        OpaqueParams_x##W p;                                                                                  \
        p.base_color.r = vload##W(i, in + 0 * n);                                                             \
        p.base_color.g = vload##W(i, in + 1 * n);                                                             \
        p.base_color.b = vload##W(i, in + 2 * n);                                                             \
        p.metallic = vload##W(i, in + 3 * n);                                                                 \
        p.roughness = vload##W(i, in + 4 * n);                                                                \
        p.specular = vload##W(i, in + 5 * n);                                                                 \
        p.specular_color.r = vload##W(i, in + 6 * n);                                                         \
        p.specular_color.g = vload##W(i, in + 7 * n);                                                         \
        p.specular_color.b = vload##W(i, in + 8 * n);                                                         \
        p.ior = vload##W(i, in + 9 * n);                                                                      \
        PROBE_COAT(W)                                                                                         \
        PROBE_SHEEN(W)                                                                                        \
        lvec##W wo, wi, u, sampled;                                                                           \
        wo.x = vload##W(i, in + 10 * n), wo.y = vload##W(i, in + 11 * n), wo.z = vload##W(i, in + 12 * n);    \
        wi.x = vload##W(i, in + 13 * n), wi.y = vload##W(i, in + 14 * n), wi.z = vload##W(i, in + 15 * n);    \
        u.x = vload##W(i, in + 16 * n), u.y = vload##W(i, in + 17 * n), u.z = vload##W(i, in + 18 * n);       \
        const OpaqueAtWo_x##W at = opaque_at_wo_x##W(&p, wo);                                                 \
        lreal##W pdf_light, pdf;                                                                              \
        lint##W delta;                                                                                        \
        const lrgb##W f_light = opaque_eval_pdf_x##W(&p, &at, wo, wi, hemisphere, &pdf_light);                \
        const lrgb##W f = opaque_sample_x##W(&p, &at, wo, u, hemisphere, &sampled, &pdf, &delta);             \
        const lreal##W v[12] = {f_light.r, f_light.g, f_light.b, pdf_light, sampled.x, sampled.y,            \
                                sampled.z, f.r, f.g, f.b, pdf, convert_float##W(-delta)};                    \
        for (int k = 0; k < 12; ++k) vstore##W(v[k], i, out + k * n); /* answer-major */                    \
    }
LANE_PROBE(8)
LANE_PROBE(16)
