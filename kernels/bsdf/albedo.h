/* albedo.h — how much light the GGX interface reflects in all, from the
 * generated tables of bsdf/albedo_tables.h; what energy conservation in
 * bsdf.h is built from. Shared by the kernels and the host.
 *
 *  - ggx_albedo(mu, r): {E, B} at view cosine mu and roughness r, bilinear in
 *    (sqrt(mu), r), the tables' grid. E is the single-scattering albedo of a
 *    white interface (F = 1), B that with Schlick's weight (1 - c)^5 as F;
 *    a Schlick interface F0 + (F90 - F0)(1 - c)^5 reflects F0 (E - B) + F90 B
 *    (schlick_albedo).
 *  - ggx_albedo_average(r): their hemispherical averages 2 ∫ E mu dmu, of the
 *    same interpolant, so the lobes below integrate exactly.
 *  - glass_albedo(table, mu, r, ior, inside): E_g, a white solid glass's whole
 *    albedo, GGX reflection and refraction under the exact Fresnel term (the
 *    refraction's 1/eta'^2 undone), trilinear in (sqrt(mu), r,
 *    (ior - 1) / (ior + 1)), for a view from outside or inside.
 *  - multiple_scattering_color: the energy that bounces between microfacets
 *    return, F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg the average of
 *    Schlick's F (Kulla and Conty, "Revisiting Physically Based Shading at
 *    Imageworks", 2017). The lobe it scales, (1 - E(mu_o))(1 - E(mu_i)) /
 *    (pi (1 - E_avg)), has albedo 1 - E(mu_o): a white interface with it
 *    reflects exactly 1, and it is reciprocal. */
#ifndef WF_BSDF_ALBEDO_H
#define WF_BSDF_ALBEDO_H

#include "wavefront/compat.h"
#include "common/sampling.h"
#include "bsdf/albedo_tables.h"

WF_DEVICE_BEGIN

/* Below this 1 - E_avg multiple scattering is left out: the tables' six
 * decimals cannot tell the loss from nothing. Its lobe, peaked at grazing
 * angles where the loss is small, is sampled by its own shape (loss_sample_mu),
 * so no weight grows as the loss vanishes. */
#define WF_ALBEDO_MIN_LOSS 1e-5f

/* The grid cell and weight of x in [0, 1] on `size` points. */
WF_INLINE int grid_cell(float x, int size, float* t) {
    const float s = min(max(x, 0.0f), 1.0f) * (float)(size - 1);
    const int i = (int)s < size - 2 ? (int)s : size - 2;
    *t = s - (float)i;
    return i;
}

/* The same on WF_ALBEDO_SIZE points. */
WF_INLINE int albedo_cell(float x, float* t) { return grid_cell(x, WF_ALBEDO_SIZE, t); }

WF_INLINE float2 ggx_albedo(float mu, float roughness) {
    float tm, tr;
    const int m = albedo_cell(sqrt(max(mu, 0.0f)), &tm), r = albedo_cell(roughness, &tr);
    float2 v[2];
    for (int k = 0; k < 2; ++k) {
        const float e0 = ggx_albedo_table[r + k][m][0], e1 = ggx_albedo_table[r + k][m + 1][0];
        const float b0 = ggx_albedo_table[r + k][m][1], b1 = ggx_albedo_table[r + k][m + 1][1];
        v[k] = make_float2(e0 + tm * (e1 - e0), b0 + tm * (b1 - b0));
    }
    return v[0] + tr * (v[1] - v[0]);
}

WF_INLINE float2 ggx_albedo_average(float roughness) {
    float tr;
    const int r = albedo_cell(roughness, &tr);
    const float2 a = make_float2(ggx_albedo_average_table[r][0], ggx_albedo_average_table[r][1]);
    const float2 b = make_float2(ggx_albedo_average_table[r + 1][0], ggx_albedo_average_table[r + 1][1]);
    return a + tr * (b - a);
}

/* The sheen lobe's albedo S(mu, r) (bsdf/sheen.h), interpolated as ggx_albedo. */
WF_INLINE float sheen_albedo(float mu, float roughness) {
    float tm, tr;
    const int m = albedo_cell(sqrt(max(mu, 0.0f)), &tm), r = albedo_cell(roughness, &tr);
    const float a = sheen_albedo_table[r][m] + tm * (sheen_albedo_table[r][m + 1] - sheen_albedo_table[r][m]);
    const float b =
        sheen_albedo_table[r + 1][m] + tm * (sheen_albedo_table[r + 1][m + 1] - sheen_albedo_table[r + 1][m]);
    return a + tr * (b - a);
}

/* The multiple-scattering lobe's shape at roughness r, (1 - E(mu)) mu dmu, as a
 * histogram over the grid's segments in x = sqrt(mu) of the grid row nearest
 * r (ggx_loss_cdf): a cosine drawn from it, and its density in solid angle
 * with a uniform azimuth. A row whose loss is nothing has no histogram
 * (loss_histogram_empty): draw nothing from it. */
WF_INLINE int loss_row(float roughness) {
    const int r = (int)(min(max(roughness, 0.0f), 1.0f) * (float)(WF_ALBEDO_SIZE - 1) + 0.5f);
    return r < WF_ALBEDO_SIZE - 1 ? r : WF_ALBEDO_SIZE - 1;
}

WF_INLINE int loss_histogram_empty(float roughness) {
    return !(ggx_loss_cdf[loss_row(roughness)][WF_ALBEDO_SIZE - 1] > 0.0f);
}

WF_INLINE float loss_sample_mu(float roughness, float u) {
    const int r = loss_row(roughness);
    int k = 0;
    while (k < WF_ALBEDO_SIZE - 2 && !(u < ggx_loss_cdf[r][k + 1])) ++k;
    const float lo = ggx_loss_cdf[r][k], hi = ggx_loss_cdf[r][k + 1];
    const float t = hi > lo ? min(max((u - lo) / (hi - lo), 0.0f), 1.0f) : 0.5f;
    const float x = ((float)k + t) / (float)(WF_ALBEDO_SIZE - 1);
    return x * x;
}

WF_INLINE float loss_pdf(float roughness, float mu) {
    if (!(mu > 0.0f)) return 0.0f;
    const int r = loss_row(roughness);
    const float x = sqrt(min(mu, 1.0f));
    const int k = min((int)(x * (float)(WF_ALBEDO_SIZE - 1)), WF_ALBEDO_SIZE - 2);
    const float mass = ggx_loss_cdf[r][k + 1] - ggx_loss_cdf[r][k];
    /* mass / h in x; / (2 x) in mu; / (2 pi) over the azimuth */
    return mass * (float)(WF_ALBEDO_SIZE - 1) / (4.0f * WF_PI * x);
}

/* Where glass_albedo's table lives: the program's own __constant copy, or, in a
 * GPU's program (WF_GLASS_TABLE_IN_SCENE), the scene buffer of the same floats:
 * NVIDIA's constant bank holds 64 KiB and the table is 96 KiB. BsdfParams
 * carries it there (bsdf.h); WF_GLASS_TABLE(p) names it either way. */
#if WF_GLASS_TABLE_IN_SCENE
typedef __global const float* GlassAlbedoTable;
#define WF_GLASS_TABLE(p) ((p)->glass_table)
#else
#ifdef __OPENCL_C_VERSION__
typedef __constant float* GlassAlbedoTable;
#else
typedef const float* GlassAlbedoTable;
#endif
#define WF_GLASS_TABLE(p) (&glass_albedo_table[0][0][0][0])
#endif

WF_INLINE float glass_albedo(GlassAlbedoTable table, float mu, float roughness, float ior, int inside) {
    float tm, tr, tx;
    const int m = albedo_cell(sqrt(max(mu, 0.0f)), &tm), r = albedo_cell(roughness, &tr);
    const int x = grid_cell((ior - 1.0f) / ((ior + 1.0f) * WF_GLASS_MAX_X), WF_GLASS_IOR_SIZE, &tx);
    const int side = inside ? 1 : 0;
    float v[2][2];
    for (int i = 0; i < 2; ++i)
        for (int k = 0; k < 2; ++k) {
            const int at = ((side * WF_GLASS_IOR_SIZE + x + i) * WF_ALBEDO_SIZE + r + k) * WF_ALBEDO_SIZE;
            GlassAlbedoTable row = table + at;
            const float lo = row[m], hi = row[m + 1];
            v[i][k] = lo + tm * (hi - lo);
        }
    const float a = v[0][0] + tr * (v[0][1] - v[0][0]), b = v[1][0] + tr * (v[1][1] - v[1][0]);
    return a + tx * (b - a);
}

/* The single-scattering albedo of a Schlick interface, from {E, B}. */
WF_INLINE float3 schlick_albedo(float2 eb, float3 f0, float f90) {
    return f0 * (eb.x - eb.y) + make_float3(f90, f90, f90) * eb.y;
}

/* Schlick's F averaged over the hemisphere, 2 ∫ F mu dmu: (1 - c)^5 averages 1/21. */
WF_INLINE float3 schlick_average(float3 f0, float f90) {
    return f0 + (make_float3(f90, f90, f90) - f0) * (1.0f / 21.0f);
}

WF_INLINE float3 multiple_scattering_color(float3 f0, float f90, float e_avg) {
    if (!(1.0f - e_avg > WF_ALBEDO_MIN_LOSS)) return make_float3(0.0f, 0.0f, 0.0f);
    const float3 f = schlick_average(f0, f90);
    return f * f * e_avg / (make_float3(1.0f, 1.0f, 1.0f) - f * (1.0f - e_avg));
}

/* (1 - E(mu_o))(1 - E(mu_i)) / (pi (1 - E_avg)) without the colour. */
WF_INLINE float multiple_scattering_lobe(float e_o, float e_i, float e_avg) {
    const float loss = 1.0f - e_avg;
    return loss > WF_ALBEDO_MIN_LOSS ? (1.0f - e_o) * (1.0f - e_i) / (WF_PI * loss) : 0.0f;
}

WF_DEVICE_END

#endif /* WF_BSDF_ALBEDO_H */
