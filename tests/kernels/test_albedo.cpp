// test_albedo.cpp — the generated albedo tables (kernels/bsdf/albedo_tables.h,
// read through bsdf/albedo.h) against an independent integral of the same
// GGX code: a deterministic quadrature over microfacet normals, where the
// generator sampled visible normals. Off the grid too, so the interpolation
// is checked with the values. Then the promises energy compensation rests
// on: the tables' averages are those of the interpolant, and the multiple-
// scattering lobe returns what single scattering loses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf/albedo.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "support/test_support.h"

namespace wf {
namespace {

using wf_device::float2;
using wf_device::float3;

struct Integral {
    double e = 0.0, b = 0.0;
};

// E and B at (mu, roughness) as ∫ D(wm) G2 |wo.wm| / mu dwm over normals wm
// whose mirror direction lies above the surface (the Jacobian dwi = 4 |wo.wm|
// dwm turns f mu_i dwi into this). The polar angle is taken through
// tan(theta_m) = alpha tan(s), s even on [0, pi/2), so that the peak of D is
// spread over the grid whatever the roughness.
Integral integrate(double mu, double roughness) {
    const float alpha = float(roughness * roughness);
    const float3 wo(float(std::sqrt(1.0 - mu * mu)), 0.0f, float(mu));
    const int ns = 1200, nphi = 400;
    Integral sum;
    for (int i = 0; i < ns; ++i) {
        const double s = (i + 0.5) * (M_PI / 2) / ns;
        const double theta = std::atan(alpha * std::tan(s));
        const double dtheta_ds = alpha / (std::cos(s) * std::cos(s)) / (1.0 + std::pow(alpha * std::tan(s), 2));
        for (int j = 0; j < nphi; ++j) {
            const double phi = (j + 0.5) * (2 * M_PI) / nphi;
            const float3 wm(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                            float(std::cos(theta)));
            const float dot_o = wf_device::dot(wo, wm);
            if (!(dot_o > 0.0f)) continue;
            const float3 wi = 2.0f * dot_o * wm - wo;
            if (!(wi.z > 0.0f)) continue;
            const double f = double(wf_device::ggx_d(wm, alpha)) * wf_device::ggx_g2(wo, wi, alpha) * dot_o / mu;
            const double dw = std::sin(theta) * dtheta_ds * (M_PI / 2 / ns) * (2 * M_PI / nphi);
            sum.e += f * dw;
            sum.b += f * dw * wf_device::schlick_weight(dot_o);
        }
    }
    return sum;
}

TEST(AlbedoTables, MatchAQuadratureOfTheBsdf) {
    double worst = 0.0;
    int points = 0;
    for (double roughness : {0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0})
        for (double mu : {0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.65, 0.8, 1.0}) {
            ++points;
            const Integral q = integrate(mu, roughness);
            const float2 t = wf_device::ggx_albedo(float(mu), float(roughness));
            EXPECT_NEAR(t.x, q.e, 0.004) << "E at mu " << mu << ", roughness " << roughness;
            EXPECT_NEAR(t.y, q.b, 0.004) << "B at mu " << mu << ", roughness " << roughness;
            worst = std::max({worst, std::fabs(t.x - q.e), std::fabs(t.y - q.b)});
        }
    char line[128];
    std::snprintf(line, sizeof line, "albedo tables vs quadrature: largest difference %.5f over %d points", worst,
                  points);
    test::report_measured(line);
}

// 2 ∫ E mu dmu of what ggx_albedo returns, by fine midpoint sums.
TEST(AlbedoTables, AveragesAreThoseOfTheInterpolant) {
    for (double roughness : {0.0, 0.13, 0.5, 0.77, 1.0}) {
        const int n = 20000;
        double e = 0.0, b = 0.0;
        for (int i = 0; i < n; ++i) {
            const double mu = (i + 0.5) / n;
            const float2 t = wf_device::ggx_albedo(float(mu), float(roughness));
            e += 2.0 * t.x * mu / n;
            b += 2.0 * t.y * mu / n;
        }
        const float2 average = wf_device::ggx_albedo_average(float(roughness));
        EXPECT_NEAR(average.x, e, 2e-5) << "roughness " << roughness;
        EXPECT_NEAR(average.y, b, 2e-5) << "roughness " << roughness;
    }
}

// With F = 1 the lobe's colour is 1 and its albedo 1 - E(mu_o): single and
// multiple scattering together reflect everything, at every roughness and mu.
TEST(AlbedoTables, MultipleScatteringReturnsWhatSingleScatteringLoses) {
    for (float roughness : {0.2f, 0.5f, 1.0f}) {
        const float e_avg = wf_device::ggx_albedo_average(roughness).x;
        const float3 white = wf_device::multiple_scattering_color(float3(1.0f), 1.0f, e_avg);
        EXPECT_NEAR(white.x, 1.0f, 1e-6f);
        for (float mu_o : {0.05f, 0.3f, 1.0f}) {
            const float e_o = wf_device::ggx_albedo(mu_o, roughness).x;
            const int n = 20000;
            double albedo = 0.0; // ∫ lobe mu_i dwi = 2 pi ∫ lobe mu_i dmu_i
            for (int i = 0; i < n; ++i) {
                const float mu_i = (i + 0.5f) / n;
                const float e_i = wf_device::ggx_albedo(mu_i, roughness).x;
                albedo += 2.0 * M_PI * wf_device::multiple_scattering_lobe(e_o, e_i, e_avg) * mu_i / n;
            }
            EXPECT_NEAR(e_o + albedo, 1.0, 1e-4) << "roughness " << roughness << ", mu " << mu_o;
        }
    }
}

} // namespace
} // namespace wf
