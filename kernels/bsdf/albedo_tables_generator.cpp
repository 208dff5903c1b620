// albedo_tables_generator.cpp — writes kernels/bsdf/albedo_tables.h: the
// directional albedo of the GGX interface of microfacet.h, computed from that
// very code compiled for the host, so the tables cannot drift from the BSDF.
//
//   build/albedo_tables_generator > kernels/bsdf/albedo_tables.h
//
// For each roughness r (alpha = r^2) and view cosine mu on a grid of
// WF_ALBEDO_SIZE points each (r and sqrt(mu) evenly from 0 to 1: the albedo
// changes fastest at grazing angles), two integrals of the single-
// scattering reflection f = F D G2 / (4 mu_o mu_i) against mu_i over the
// hemisphere, by visible-normal sampling (the estimator G2 / G1 of Heitz 2018)
// over a Hammersley point set (every u.x distinct, so GGX's long tail is not
// cut into rows):
//   E(mu, r): with F = 1, the albedo of a white interface;
//   B(mu, r): with F = (1 - wo.wm)^5, Schlick's weight.
// Schlick's F = F0 + (F90 - F0) w is linear in F0 and F90, so the albedo of any
// Schlick interface is F0 (E - B) + F90 B. Then for each r the hemispherical
// averages 2 ∫ E mu dmu and 2 ∫ B mu dmu of the tables as bsdf/albedo.h
// interpolates them (piecewise linear in sqrt(mu), integrated exactly), so that an
// energy-compensating lobe built from them integrates to what it promises.
// Then, per roughness, the cumulative distribution over the grid's segments
// in x = sqrt(mu) of (1 - E) mu dmu, E as interpolated: the shape of the
// multiple-scattering lobe, which bsdf/albedo.h samples as a histogram.
// Then the sheen lobe's albedo (bsdf/sheen.h), S(mu, r) = ∫ D V mu_i dw_i,
// on the same grid, by a midpoint rule in (sqrt(mu_i), phi_i) (the lobe
// peaks at grazing angles, where sqrt spreads the rows).
// Then the albedo E_g of a white solid glass: GGX reflection and refraction
// weighed by the exact Fresnel term, the refraction's 1/eta'^2 undone, by
// the same visible normals (F G2 / G1 reflected, (1 - F) G2 / G1 refracted,
// for each normal), from outside (eta' = ior) and inside (eta' = 1 / ior), on
// the same grid in sqrt(mu) and r (a coarser one missed a dip at grazing
// views and low roughness by 3.5%) and WF_GLASS_IOR_SIZE points of
// (ior - 1) / (ior + 1) from 0 to kGlassMaxX, where E_g changes slowly.
// The CTest AlbedoTables.MatchTheirGenerator reruns this and compares bytes.
#include <algorithm>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf/sheen.h"

namespace {

constexpr int kSize = 32;       // grid points in mu and in roughness
constexpr uint32_t kSamples = 1u << 16; // visible normals per entry
constexpr float kMinMu = 1e-4f; // the mu = 0 column: grazing, where E -> 0 continuously
constexpr float kMinAlpha = 1e-4f; // the r = 0 row: as smooth as float GGX allows
constexpr int kGlassIorSize = 12; // grid points of the glass table in ior
constexpr uint32_t kGlassSamples = 1u << 14;
constexpr float kGlassMaxX = 0.5f; // (ior - 1) / (ior + 1) up to ior 3

// Van der Corput's base-2 radical inverse: i's bits mirrored after the point.
float radical_inverse(uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
    i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
    i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
    i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
    return float(i) * 0x1p-32f;
}

struct Entry {
    double e = 0.0, b = 0.0;
};

float grid_alpha(float roughness) { return roughness * roughness > kMinAlpha ? roughness * roughness : kMinAlpha; }

Entry integrate(float mu, float roughness) {
    using namespace wf_device;
    const float alpha = grid_alpha(roughness);
    const float3 wo = make_float3(std::sqrt(1.0f - mu * mu), 0.0f, mu);
    Entry sum;
    for (uint32_t i = 0; i < kSamples; ++i) {
        const float2 u = make_float2((i + 0.5f) / kSamples, radical_inverse(i));
        const float3 wm = ggx_sample_visible(wo, alpha, u);
        const float dot_o = dot(wo, wm);
        const float3 wi = 2.0f * dot_o * wm - wo;
        if (!(wi.z > 0.0f)) continue;
        const double weight = double(ggx_g2(wo, wi, alpha)) / double(ggx_g1(wo, alpha));
        sum.e += weight;
        sum.b += weight * double(schlick_weight(dot_o));
    }
    return {sum.e / kSamples, sum.b / kSamples};
}

// E_g at view cosine mu (the view on the side of relative index eta).
double glass_albedo(float mu, float roughness, float eta) {
    using namespace wf_device;
    const float alpha = grid_alpha(roughness);
    const float3 wo = make_float3(std::sqrt(1.0f - mu * mu), 0.0f, mu);
    const double g1 = ggx_g1(wo, alpha);
    double sum = 0.0;
    for (uint32_t i = 0; i < kGlassSamples; ++i) {
        const float2 u = make_float2((i + 0.5f) / kGlassSamples, radical_inverse(i));
        const float3 wm = ggx_sample_visible(wo, alpha, u);
        const float dot_o = dot(wo, wm);
        const float f = fresnel_dielectric(dot_o, eta);
        const float3 wr = 2.0f * dot_o * wm - wo;
        if (wr.z > 0.0f) sum += f * double(ggx_g2(wo, wr, alpha)) / g1;
        float3 wt;
        if (fresnel_refract(wo, wm, eta, &wt) && wt.z < 0.0f) sum += (1.0f - f) * double(ggx_g2(wo, wt, alpha)) / g1;
    }
    return sum / kGlassSamples;
}

double sheen_albedo(float mu, float roughness) {
    using namespace wf_device;
    constexpr int kRows = 256, kColumns = 256; // in sqrt(mu_i), and in phi_i over [0, pi] (the lobe is even in phi)
    const float3 wo = make_float3(std::sqrt(1.0f - mu * mu), 0.0f, mu);
    double sum = 0.0;
    for (int i = 0; i < kRows; ++i) {
        const double x = (i + 0.5) / kRows, mu_i = x * x; // dmu_i = 2 x dx
        const double s = std::sqrt(1.0 - mu_i * mu_i);
        for (int j = 0; j < kColumns; ++j) {
            const double phi = (j + 0.5) * 3.14159265358979323846 / kColumns;
            const float3 wi = make_float3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(mu_i));
            sum += double(sheen_eval(wo, wi, roughness)) * mu_i * 2.0 * x;
        }
    }
    return sum * (1.0 / kRows) * (2.0 * 3.14159265358979323846 / kColumns);
}

// The grid: roughness r and sqrt(mu) evenly from 0 to 1, the mu = 0 column at kMinMu.
float grid_roughness(int r) { return float(r) / (kSize - 1); }
float grid_mu(int m) {
    const float x = float(m) / (kSize - 1);
    return m == 0 ? kMinMu : x * x;
}

// Values as printed, so that the averages are those of the printed tables.
double printed(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6f", v);
    return std::strtod(text, nullptr);
}

// 2 ∫_0^1 f mu dmu of f piecewise linear in x = sqrt(mu) through (x_i, f_i):
// 4 ∫_0^1 f(x) x^3 dx, a polynomial of degree 4 on each segment, which
// three-point Gauss-Legendre integrates exactly.
double hemispherical_average(const std::vector<double>& f) {
    const double nodes[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    const double weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    const double h = 1.0 / (kSize - 1);
    double sum = 0.0;
    for (int i = 0; i + 1 < kSize; ++i)
        for (int k = 0; k < 3; ++k) {
            const double t = 0.5 * (1.0 + nodes[k]), x = (i + t) * h;
            sum += 0.5 * h * weights[k] * (f[i] + t * (f[i + 1] - f[i])) * x * x * x;
        }
    return 4.0 * sum;
}

// The cumulative masses at the grid points of (1 - E(x)) 2 x^3 dx (that is
// (1 - E) mu dmu), E piecewise linear through `e`, normalised to end at 1:
// a polynomial of degree 4 on each segment, integrated exactly by three-point
// Gauss-Legendre. All zero when E is 1 everywhere.
std::vector<double> loss_cdf(const std::vector<double>& e) {
    const double nodes[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    const double weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    const double h = 1.0 / (kSize - 1);
    std::vector<double> cdf(kSize, 0.0);
    for (int i = 0; i + 1 < kSize; ++i) {
        double mass = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double t = 0.5 * (1.0 + nodes[k]), x = (i + t) * h;
            mass += 0.5 * h * weights[k] * (1.0 - (e[i] + t * (e[i + 1] - e[i]))) * 2.0 * x * x * x;
        }
        cdf[i + 1] = cdf[i] + std::max(mass, 0.0);
    }
    const double total = cdf[kSize - 1];
    for (double& c : cdf) c = total > 0.0 ? c / total : 0.0;
    return cdf;
}

} // namespace

int main() {
    std::printf("/* albedo_tables.h — GENERATED by albedo_tables_generator.cpp beside it; do not edit.\n"
                " * Regenerate: build/albedo_tables_generator > kernels/bsdf/albedo_tables.h\n"
                " * ggx_albedo_table[r][mu] = {E, B}: the GGX interface's directional albedo with\n"
                " * F = 1 and with F = Schlick's weight, roughness r and sqrt(mu), mu the\n"
                " * view cosine, each on %d points from 0 to 1; ggx_albedo_average_table[r]:\n"
                " * their hemispherical averages; ggx_loss_cdf[r][i]: the distribution of\n"
                " * (1 - E) mu dmu up to grid point i; sheen_albedo_table[r][mu]: the sheen lobe's\n"
                " * albedo on the same grid; glass_albedo_table[inside][ior][r][mu]: a white solid\n"
                " * glass's albedo, reflection and refraction, on the same grid and %d points of\n"
                " * (ior - 1) / (ior + 1) up to %.2f. Read through bsdf/albedo.h. */\n",
                kSize, kGlassIorSize, double(kGlassMaxX));
    std::printf("#ifndef WF_ALBEDO_TABLES_H\n#define WF_ALBEDO_TABLES_H\n\n#include \"wavefront/compat.h\"\n\n");
    std::printf("#define WF_ALBEDO_SIZE %d\n#define WF_GLASS_IOR_SIZE %d\n#define WF_GLASS_MAX_X %.2ff\n\n"
                "WF_DEVICE_BEGIN\n\n",
                kSize, kGlassIorSize, double(kGlassMaxX));
    std::vector<std::vector<Entry>> table(kSize, std::vector<Entry>(kSize));
    std::printf("WF_CONSTANT float ggx_albedo_table[WF_ALBEDO_SIZE][WF_ALBEDO_SIZE][2] = {\n");
    for (int r = 0; r < kSize; ++r) {
        std::printf("    {");
        for (int m = 0; m < kSize; ++m) {
            const Entry e = integrate(grid_mu(m), grid_roughness(r));
            table[r][m] = {printed(e.e), printed(e.b)};
            std::printf("%s{%.6ff, %.6ff}", m ? (m % 4 ? ", " : ",\n     ") : "", e.e, e.b);
        }
        std::printf("},\n");
    }
    std::printf("};\n\nWF_CONSTANT float ggx_albedo_average_table[WF_ALBEDO_SIZE][2] = {\n");
    for (int r = 0; r < kSize; ++r) {
        std::vector<double> e(kSize), b(kSize);
        for (int m = 0; m < kSize; ++m) {
            e[m] = table[r][m].e;
            b[m] = table[r][m].b;
        }
        std::printf("    {%.6ff, %.6ff},\n", hemispherical_average(e), hemispherical_average(b));
    }
    std::printf("};\n\nWF_CONSTANT float ggx_loss_cdf[WF_ALBEDO_SIZE][WF_ALBEDO_SIZE] = {\n");
    for (int r = 0; r < kSize; ++r) {
        std::vector<double> e(kSize);
        for (int m = 0; m < kSize; ++m) e[m] = table[r][m].e;
        const std::vector<double> cdf = loss_cdf(e);
        std::printf("    {");
        for (int m = 0; m < kSize; ++m) std::printf("%s%.7ff", m ? (m % 8 ? ", " : ",\n     ") : "", cdf[m]);
        std::printf("},\n");
    }
    std::printf("};\n\nWF_CONSTANT float sheen_albedo_table[WF_ALBEDO_SIZE][WF_ALBEDO_SIZE] = {\n");
    for (int r = 0; r < kSize; ++r) {
        std::printf("    {");
        for (int m = 0; m < kSize; ++m)
            std::printf("%s%.6ff", m ? (m % 8 ? ", " : ",\n     ") : "", sheen_albedo(grid_mu(m), grid_roughness(r)));
        std::printf("},\n");
    }
    std::printf("};\n\n/* 96 KiB: more than a GPU's constant bank holds, so a GPU's program reads it from\n"
                " * the scene's glass_albedo buffer instead (bsdf/albedo.h). */\n"
                "#if !WF_GLASS_TABLE_IN_SCENE\n"
                "WF_CONSTANT float glass_albedo_table[2][WF_GLASS_IOR_SIZE][WF_ALBEDO_SIZE][WF_ALBEDO_SIZE] = {\n");
    for (int inside = 0; inside < 2; ++inside) {
        std::printf("    {\n");
        for (int i = 0; i < kGlassIorSize; ++i) {
            const float x = kGlassMaxX * float(i) / (kGlassIorSize - 1), ior = (1.0f + x) / (1.0f - x);
            std::printf("        {");
            for (int r = 0; r < kSize; ++r) {
                std::printf("%s{", r ? ",\n         " : "");
                for (int m = 0; m < kSize; ++m)
                    std::printf("%s%.5ff", m ? (m % 8 ? ", " : ",\n          ") : "",
                                glass_albedo(grid_mu(m), grid_roughness(r), inside ? 1.0f / ior : ior));
                std::printf("}");
            }
            std::printf("},\n");
        }
        std::printf("    },\n");
    }
    std::printf("};\n#endif\n\nWF_DEVICE_END\n\n#endif /* WF_ALBEDO_TABLES_H */\n");
    return 0;
}
