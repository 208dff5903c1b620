/* bsdf_lanes.cl — the kernels of bench/bsdf_lanes.cpp: one BSDF evaluation
 * per (wo, wi) pair, three ways, to measure what shading in SIMD lanes would
 * buy on a CPU OpenCL device (issue 16).
 *
 *   general_eval      the renderer's own bsdf_interface_eval: every lobe kind
 *                     behind branches, one pair per work-item (what shade runs)
 *   metal_scalar      one BSDF kind only (an opaque GGX metal), written without
 *                     branches, one pair per work-item
 *   metal_lanes       the same arithmetic in float8: eight pairs per work-item
 *
 * metal_* restate the GGX metal of kernels/bsdf (microfacet.h, fresnel.h)
 * operation for operation, for metallic = 1; bsdf_lanes.cpp compares their
 * results with general_eval's (f agrees to the bit; the pdf differs by up to
 * 19 ulp in a quarter of the pairs, from where the dot products round). */
#include "bsdf/bsdf.h"

/* The metal's parameters are kernel arguments: BsdfParams is a device struct. */
#define METAL_ARGS __global const float4 *wo, __global const float4 *wi, __global float4 *out, float3 base_color, float roughness
#define METAL_PARAMS                                                                                             \
    BsdfParams p = {0};                                                                                           \
    p.base_color = base_color;                                                                                    \
    p.metallic = 1.0f;                                                                                            \
    p.roughness = roughness;                                                                                      \
    p.ior = 1.5f;                                                                                                 \
    p.specular = 1.0f;                                                                                            \
    p.specular_color = (float3)(1.0f)

__kernel void general_eval(METAL_ARGS) {
    METAL_PARAMS;
    const size_t i = get_global_id(0);
    float pdf;
    const float3 f = bsdf_interface_eval(&p, wo[i].xyz, wi[i].xyz, &pdf);
    out[i] = (float4)(f, pdf);
}

/* The GGX metal's f and pdf (reflection only, metallic = 1), in TYPE float or
 * float8, OK_TYPE the matching int type: kernels/bsdf's bsdf_interface_eval
 * with its branches turned into selects. */
#define METAL_EVAL(TYPE, OK_TYPE, ox, oy, oz, ix, iy, iz, fr, fg, fb, pdf)                                       \
    do {                                                                                                          \
        TYPE mx = ox + ix, my = oy + iy, mz = oz + iz;                                                            \
        const TYPE len2 = mx * mx + my * my + mz * mz;                                                            \
        const TYPE len = sqrt(len2);                                                                              \
        mx = mx / len; my = my / len; mz = mz / len;                                                              \
        const TYPE dot_o = ox * mx + oy * my + oz * mz;                                                           \
        const float alpha = p.roughness * p.roughness, a2 = alpha * alpha;                                        \
        const TYPE t = mz * mz + (mx * mx + my * my) / a2;                                                        \
        const TYPE d = 1.0f / (WF_PI * a2 * t * t);                                                               \
        const TYPE a2t2_o = alpha * alpha * (ox * ox + oy * oy) / (oz * oz);                                      \
        const TYPE a2t2_i = alpha * alpha * (ix * ix + iy * iy) / (iz * iz);                                      \
        const TYPE lambda_o = 0.5f * a2t2_o / (1.0f + sqrt(1.0f + a2t2_o));                                       \
        const TYPE lambda_i = 0.5f * a2t2_i / (1.0f + sqrt(1.0f + a2t2_i));                                       \
        const TYPE g = 1.0f / (1.0f + lambda_o + lambda_i);                                                       \
        const TYPE pdf_wm = 1.0f / (1.0f + lambda_o) * fmax(0.0f, dot_o) * d / fabs(oz);                          \
        const TYPE m = 1.0f - fmin(fabs(dot_o), 1.0f), m2 = m * m, s = m2 * m2 * m;                               \
        const OK_TYPE ok = (oz * iz > 0.0f) & (len2 > 0.0f) & (dot_o * oz > 0.0f) &                               \
                            ((ix * mx + iy * my + iz * mz) * iz > 0.0f);                                          \
        const TYPE w = select((TYPE)(0.0f), d * g / (4.0f * fabs(oz) * fabs(iz)), ok);                            \
        fr = (p.base_color.x + (1.0f - p.base_color.x) * s) * w;                                                  \
        fg = (p.base_color.y + (1.0f - p.base_color.y) * s) * w;                                                  \
        fb = (p.base_color.z + (1.0f - p.base_color.z) * s) * w;                                                  \
        pdf = select((TYPE)(0.0f), pdf_wm / (4.0f * fabs(dot_o)), ok);                                            \
    } while (0)

__kernel void metal_scalar(METAL_ARGS) {
    METAL_PARAMS;
    const size_t i = get_global_id(0);
    float fr, fg, fb, pdf;
    METAL_EVAL(float, int, wo[i].x, wo[i].y, wo[i].z, wi[i].x, wi[i].y, wi[i].z, fr, fg, fb, pdf);
    out[i] = (float4)(fr, fg, fb, pdf);
}

/* Eight consecutive pairs, lane k holding pair 8i + k. */
#define LANES(a, c) (float8)(a[b].c, a[b + 1].c, a[b + 2].c, a[b + 3].c, a[b + 4].c, a[b + 5].c, a[b + 6].c, a[b + 7].c)
__kernel void metal_lanes(METAL_ARGS) {
    METAL_PARAMS;
    const size_t b = 8 * get_global_id(0);
    float8 fr, fg, fb, pdf;
    METAL_EVAL(float8, int8, LANES(wo, x), LANES(wo, y), LANES(wo, z), LANES(wi, x), LANES(wi, y), LANES(wi, z), fr,
               fg, fb, pdf);
    const float r[8] = {fr.s0, fr.s1, fr.s2, fr.s3, fr.s4, fr.s5, fr.s6, fr.s7};
    const float g[8] = {fg.s0, fg.s1, fg.s2, fg.s3, fg.s4, fg.s5, fg.s6, fg.s7};
    const float bl[8] = {fb.s0, fb.s1, fb.s2, fb.s3, fb.s4, fb.s5, fb.s6, fb.s7};
    const float d[8] = {pdf.s0, pdf.s1, pdf.s2, pdf.s3, pdf.s4, pdf.s5, pdf.s6, pdf.s7};
    for (int k = 0; k < 8; ++k) out[b + k] = (float4)(r[k], g[k], bl[k], d[k]);
}
