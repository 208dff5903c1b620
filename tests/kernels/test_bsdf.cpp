// test_bsdf.cpp — the glTF BSDF of bsdf/bsdf.h, compiled for the host as the
// kernels compile it for the device (and checked against the device):
//  1. sampling draws directions with the density bsdf_pdf states (chi-square
//     over 16 x 32 (cos theta, phi) cells of the sphere, 1e6 samples each);
//  2. that density integrates to the probability of a non-Dirac sample;
//  3. reflection is reciprocal, transmission generalised-reciprocal;
//  4. nothing reflects more than it receives, and clear glass (smooth or
//     rough), a white mirror and every opaque white material lose nothing;
//  5. Dirac lobes reflect and refract exactly, with total internal reflection;
//  6. no NaN or Inf at any roughness, at grazing or normal incidence.
// Over 400 lines on purpose: the six properties are checked over one list of
// materials and one set of sampled tables, computed once for all of them.
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bsdf/bsdf.h"
#include "device/kernel_sources.h"
#include "support/statistics.h"
#include "support/test_support.h"

namespace wf {
namespace {

using glm::vec3;
using wf_device::BsdfParams;
using wf_device::BsdfSample;

BsdfParams material(vec3 base, float metallic, float roughness, float transmission = 0.0f, float ior = 1.5f,
                    uint32_t hemisphere = WF_HEMISPHERE_COSINE) {
    BsdfParams p;
    p.base_color = base;
    p.metallic = metallic;
    p.roughness = roughness;
    p.transmission = transmission;
    p.ior = ior;
    p.specular = 1.0f;
    p.specular_color = vec3(1.0f);
    p.thin_walled = 0;
    p.clearcoat = 0.0f;
    p.clearcoat_roughness = 0.0f;
    p.sheen_color = vec3(0.0f);
    p.sheen_roughness = 0.0f;
    p.hemisphere = hemisphere;
    return p;
}

// The same material as a thin wall (glTF's transmission without KHR_materials_volume).
BsdfParams thin(BsdfParams p) {
    p.thin_walled = 1;
    return p;
}

// The same material under a clear coat (KHR_materials_clearcoat).
BsdfParams coated(BsdfParams p, float clearcoat, float roughness) {
    p.clearcoat = clearcoat;
    p.clearcoat_roughness = roughness;
    return p;
}

// The same material under a sheen (KHR_materials_sheen).
BsdfParams sheened(BsdfParams p, vec3 color, float roughness) {
    p.sheen_color = color;
    p.sheen_roughness = roughness;
    return p;
}

// Seen from outside only: opaque and thin-walled materials.
bool outside_only(const BsdfParams& p) { return p.transmission == 0.0f || p.thin_walled; }

// A unit direction with the given cos theta, at azimuth 0.3 rad (off the axes).
vec3 direction_at(float cos_theta) {
    const float s = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    return vec3(s * std::cos(0.3f), s * std::sin(0.3f), cos_theta);
}

struct Config {
    std::string name;
    BsdfParams p;
    vec3 wo;
};

// Every material at several wo: opaque ones from outside, transmissive ones
// from both sides, grazing (|wo.z| = 0.05) and exactly normal included.
std::vector<Config> configs() {
    struct Named {
        std::string name;
        BsdfParams p;
    };
    const vec3 white(1.0f);
    const std::vector<Named> opaque = {
        {"diffuse (ior 1)", material(white, 0.0f, 1.0f, 0.0f, 1.0f)},
        {"diffuse uniform-hemisphere", material(white, 0.0f, 1.0f, 0.0f, 1.0f, WF_HEMISPHERE_UNIFORM)},
        {"metal r0.07", material(white, 1.0f, 0.07f)},
        {"metal r0.1", material(white, 1.0f, 0.1f)},
        {"metal r0.3", material(white, 1.0f, 0.3f)},
        {"metal r0.7", material(white, 1.0f, 0.7f)},
        {"metal r1", material(white, 1.0f, 1.0f)},
        {"dielectric r0.2", material(white, 0.0f, 0.2f)},
        {"dielectric r0.5", material(white, 0.0f, 0.5f)},
        {"smooth dielectric (delta + diffuse)", material(white, 0.0f, 0.0f)},
        {"specular colour r0.4", [] {
             BsdfParams p = material(vec3(0.5f, 0.6f, 0.7f), 0.0f, 0.4f);
             p.specular_color = vec3(2.0f, 1.0f, 0.3f);
             return p;
         }()},
        {"thin glass r0.3", thin(material(white, 0.0f, 0.3f, 1.0f, 1.5f))},
        {"thin mix t0.5 r0.6", thin(material(vec3(0.9f, 0.5f, 0.2f), 0.2f, 0.6f, 0.5f, 1.5f))},
        {"coat r0.3 over dielectric r0.7", coated(material(white, 0.0f, 0.7f), 1.0f, 0.3f)},
        {"coat r1 over metal r0.4", coated(material(white, 1.0f, 0.4f), 1.0f, 1.0f)},
        {"smooth coat over metal r0.3", coated(material(white, 1.0f, 0.3f), 1.0f, 0.0f)},
        {"half coat r0.5 over colour r0.5", coated(material(vec3(0.8f, 0.3f, 0.1f), 0.0f, 0.5f), 0.5f, 0.5f)},
        {"white sheen r0.5 over dielectric r0.6", sheened(material(white, 0.0f, 0.6f), white, 0.5f)},
        {"white sheen r0 over diffuse", sheened(material(white, 0.0f, 1.0f), white, 0.0f)},
        {"red sheen r0.3 under coat over metal", coated(sheened(material(white, 1.0f, 0.3f), vec3(1, 0, 0), 0.3f), 1.0f, 0.2f)},
    };
    const std::vector<Named> transmissive = {
        {"rough glass r0.3 ior1.5", material(white, 0.0f, 0.3f, 1.0f, 1.5f)},
        {"rough glass r0.3 ior1.33", material(white, 0.0f, 0.3f, 1.0f, 1.33f)},
        {"mix t0.5 m0.3 r0.5", material(vec3(0.9f, 0.5f, 0.2f), 0.3f, 0.5f, 0.5f, 1.5f)},
        {"coloured glass r0.4", [] {
             BsdfParams p = material(vec3(0.8f, 0.9f, 1.0f), 0.0f, 0.4f, 1.0f, 1.5f);
             p.specular_color = vec3(1.5f, 1.0f, 0.5f);
             return p;
         }()},
    };
    std::vector<Config> out;
    for (const Named& m : opaque)
        for (float c : {1.0f, 0.6f, 0.05f}) out.push_back({m.name + " wo.z " + std::to_string(c), m.p, direction_at(c)});
    for (const Named& m : transmissive)
        for (float c : {1.0f, 0.6f, 0.05f, -0.6f, -0.05f})
            out.push_back({m.name + " wo.z " + std::to_string(c), m.p, direction_at(c)});
    return out;
}

// ---------------------------------------------------------------------------
// Integration of the pdf over cells of the sphere, by adaptive Simpson in
// (cos theta, phi), where the solid angle is dcos dphi.

double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
                        double whole, double eps, int depth) {
    const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    const double flm = f(lm), frm = f(rm);
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const double delta = left + right - whole;
    if (depth <= 0 || std::fabs(delta) <= 15.0 * eps) return left + right + delta / 15.0;
    return adaptive_simpson(f, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1) +
           adaptive_simpson(f, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1);
}

// Starts from `pieces` equal parts, so that no lobe hides between the first samples.
double integrate(const std::function<double(double)>& f, double a, double b, double eps, int pieces) {
    double sum = 0.0;
    for (int i = 0; i < pieces; ++i) {
        const double lo = a + (b - a) * i / pieces, hi = a + (b - a) * (i + 1) / pieces;
        const double flo = f(lo), fm = f(0.5 * (lo + hi)), fhi = f(hi);
        sum += adaptive_simpson(f, lo, hi, flo, fm, fhi, (hi - lo) / 6.0 * (flo + 4.0 * fm + fhi), eps / pieces, 10);
    }
    return sum;
}

constexpr int kThetaCells = 16, kPhiCells = 32;
constexpr double kPi = 3.14159265358979323846;

int cell_of(vec3 w) {
    const double c = std::clamp(double(w.z), -1.0, 1.0);
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0.0) phi += 2.0 * kPi;
    const int i = std::min(kThetaCells - 1, int((c + 1.0) * 0.5 * kThetaCells));
    const int j = std::min(kPhiCells - 1, int(phi / (2.0 * kPi) * kPhiCells));
    return i * kPhiCells + j;
}

std::vector<double> cell_probabilities(const BsdfParams& p, vec3 wo) {
    std::vector<double> out(kThetaCells * kPhiCells);
    for (int i = 0; i < kThetaCells; ++i) {
        const double c0 = -1.0 + 2.0 * i / kThetaCells, c1 = -1.0 + 2.0 * (i + 1) / kThetaCells;
        for (int j = 0; j < kPhiCells; ++j) {
            const double p0 = 2.0 * kPi * j / kPhiCells, p1 = 2.0 * kPi * (j + 1) / kPhiCells;
            auto inner = [&](double c) {
                const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
                return integrate(
                    [&](double phi) {
                        const vec3 wi(float(s * std::cos(phi)), float(s * std::sin(phi)), float(c));
                        return double(wf_device::bsdf_pdf(&p, wo, wi));
                    },
                    p0, p1, 1e-8, 2);
            };
            out[i * kPhiCells + j] = integrate(inner, c0, c1, 2e-7, 2);
        }
    }
    return out;
}

struct Histogram {
    std::vector<double> counts = std::vector<double>(kThetaCells * kPhiCells, 0.0);
    double delta = 0.0, failed = 0.0;
};

// u from a fixed-seed generator; float uniforms in [0, 1).
vec3 uniforms(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    return vec3(u(rng), u(rng), u(rng));
}

Histogram sample_histogram(const BsdfParams& p, vec3 wo, int n, uint32_t seed) {
    std::mt19937 rng(seed);
    Histogram h;
    for (int k = 0; k < n; ++k) {
        const BsdfSample s = wf_device::bsdf_sample(&p, wo, uniforms(rng));
        if (!(s.pdf > 0.0f)) h.failed += 1.0;
        else if (s.delta) h.delta += 1.0;
        else h.counts[cell_of(s.wi)] += 1.0;
    }
    return h;
}

struct Measured {
    Config config;
    double p_value, integral, delta_fraction, failed_fraction;
    int dof;
};

// Both the chi-square test and the integral test read these; computed once.
const std::vector<Measured>& chi_square_results() {
    static const std::vector<Measured> results = [] {
        std::vector<Measured> out;
        const int n = 1000000;
        uint32_t seed = 1;
        for (const Config& c : configs()) {
            const Histogram h = sample_histogram(c.p, c.wo, n, seed++);
            const std::vector<double> prob = cell_probabilities(c.p, c.wo);
            std::vector<double> expected(prob.size());
            double integral = 0.0;
            for (size_t i = 0; i < prob.size(); ++i) {
                expected[i] = prob[i] * n;
                integral += prob[i];
            }
            const test::ChiSquare chi = test::chi_square_test(h.counts, expected);
            out.push_back({c, chi.p_value, integral, h.delta / n, h.failed / n, chi.dof});
        }
        return out;
    }();
    return results;
}

TEST(Bsdf, SamplingMatchesPdfChiSquare) {
    const auto& results = chi_square_results();
    // Šidák: the family of all configurations fails by chance with probability 1%.
    const double threshold = 1.0 - std::pow(1.0 - 0.01, 1.0 / results.size());
    for (const Measured& m : results) {
        char line[256];
        std::snprintf(line, sizeof line, "chi2 %-48s p = %.4f (dof %d)", m.config.name.c_str(), m.p_value, m.dof);
        test::report_measured(line);
        EXPECT_GT(m.p_value, threshold) << m.config.name;
    }
}

TEST(Bsdf, PdfIntegratesToNonDeltaProbability) {
    for (const Measured& m : chi_square_results()) {
        // Sampling ends in a Dirac lobe, in a non-Dirac direction, or in no
        // direction (reflected below the horizon, refraction blocked): the
        // density covers exactly the second.
        const double expected = 1.0 - m.delta_fraction - m.failed_fraction;
        char line[256];
        std::snprintf(line, sizeof line, "integral %-48s %.5f (1 - delta %.4f - failed %.4f = %.5f)",
                      m.config.name.c_str(), m.integral, m.delta_fraction, m.failed_fraction, expected);
        test::report_measured(line);
        EXPECT_NEAR(m.integral, expected, 1e-2) << m.config.name;
    }
}

// ---------------------------------------------------------------------------

vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> n;
    return glm::normalize(vec3(n(rng), n(rng), n(rng)));
}

// The index of refraction on the side of w: 1 outside, ior inside.
float side_index(const BsdfParams& p, vec3 w) { return w.z > 0.0f ? 1.0f : p.ior; }

TEST(Bsdf, Reciprocity) {
    std::mt19937 rng(7);
    int reflections = 0, transmissions = 0;
    double worst_transmission = 0.0;
    for (const Config& c : configs()) {
        if (c.wo.z < 0.0f || c.wo.z != 1.0f) continue; // one per material
        // A clear coat or a sheen weighs what lies below it by its albedo at
        // wo alone (bsdf_eval_pdf): energy-conserving, by design not reciprocal.
        if (c.p.clearcoat > 0.0f || c.p.sheen_color != vec3(0.0f)) continue;
        // A rough solid glass's single scattering is divided by its albedo at
        // wo, E_g(mu_o), as well: a clear glass (metallic 0, transmission 1)
        // is that alone, so the single scattering is checked with it divided
        // out; a mixed one is left out.
        const bool glass_scaled = wf_device::bsdf_has_inside(&c.p) && !wf_device::bsdf_interface_smooth(&c.p);
        if (glass_scaled && (c.p.metallic != 0.0f || c.p.transmission != 1.0f)) continue;
        const auto single = [&](vec3 wo, vec3 wi) {
            const vec3 f = wf_device::bsdf_eval(&c.p, wo, wi);
            return glass_scaled ? f / wf_device::bsdf_at_wo(&c.p, wo).glass_scale : f;
        };
        for (int k = 0; k < 2000; ++k) {
            vec3 wo = random_unit(rng), wi = random_unit(rng);
            if (c.p.transmission == 0.0f) wo.z = std::fabs(wo.z), wi.z = std::fabs(wi.z);
            if (c.p.thin_walled) {
                // A thin wall is the same from both sides: light from wi below
                // is what the wall, turned over, sends from -wi to -wo.
                wo.z = std::fabs(wo.z);
                const vec3 a = wf_device::bsdf_eval(&c.p, wo, wi);
                const vec3 b = wi.z > 0.0f ? wf_device::bsdf_eval(&c.p, wi, wo)
                                           : wf_device::bsdf_eval(&c.p, vec3(wi.x, wi.y, -wi.z), vec3(wo.x, wo.y, -wo.z));
                ++(wi.z > 0.0f ? reflections : transmissions);
                for (int ch = 0; ch < 3; ++ch)
                    ASSERT_NEAR(a[ch], b[ch], 1e-4f * std::max(a[ch], b[ch]) + 1e-12f) << c.name;
                continue;
            }
            const vec3 a = single(wo, wi), b = single(wi, wo);
            if (wo.z * wi.z > 0.0f) {
                ++reflections;
                for (int ch = 0; ch < 3; ++ch)
                    ASSERT_NEAR(a[ch], b[ch], 1e-4f * std::max(a[ch], b[ch]) + 1e-12f) << c.name;
            } else {
                // f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2 for radiance BTDFs
                // (Veach's thesis, 5.14), n_o and n_i the indices on wo's and
                // wi's sides. Near the critical angle 1 - F has an infinite
                // slope in cos, and float rounding of the half vector is
                // amplified there: pairs with Fresnel transmittance below 0.05
                // are left out, and the tolerance is 5e-3 (measured worst: 1.8e-3).
                const float no2 = side_index(c.p, wo) * side_index(c.p, wo);
                const float ni2 = side_index(c.p, wi) * side_index(c.p, wi);
                const float etap = wo.z > 0.0f ? c.p.ior : 1.0f / c.p.ior;
                vec3 wm = glm::normalize(wi * etap + wo);
                if (wm.z < 0.0f) wm = -wm;
                if (1.0f - wf_device::fresnel_dielectric(glm::dot(wo, wm), c.p.ior) < 0.05f) continue;
                ++transmissions;
                for (int ch = 0; ch < 3; ++ch) {
                    const float x = a[ch] / no2, y = b[ch] / ni2;
                    if (x > 0.0f || y > 0.0f)
                        worst_transmission = std::max(worst_transmission, double(std::fabs(x - y) / std::max(x, y)));
                }
            }
        }
    }
    test::report_measured("reciprocity: " + std::to_string(reflections) + " reflection and " +
                          std::to_string(transmissions) + " transmission pairs, worst relative deviation " +
                          std::to_string(worst_transmission));
    EXPECT_LT(worst_transmission, 5e-3);
}

// The mean of f |cos| / pdf over n samples and its standard error; a
// transmission's weight multiplied by eta'^2 when `undo_eta2`.
struct Albedo {
    double mean, standard_error;
};
Albedo albedo(const BsdfParams& p, vec3 wo, int n, uint32_t seed, bool undo_eta2) {
    std::mt19937 rng(seed);
    double sum = 0.0, sum2 = 0.0;
    for (int k = 0; k < n; ++k) {
        const BsdfSample s = wf_device::bsdf_sample(&p, wo, uniforms(rng));
        double w = 0.0;
        if (s.pdf > 0.0f) {
            w = double(wf_device::bsdf_luminance(s.f)) * std::fabs(s.wi.z) / s.pdf;
            if (undo_eta2 && !p.thin_walled && s.wi.z * wo.z < 0.0f) {
                const double etap = wo.z > 0.0f ? p.ior : 1.0 / p.ior;
                w *= etap * etap;
            }
        }
        sum += w;
        sum2 += w * w;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

TEST(Bsdf, WhiteFurnace) {
    const int n = 200000;
    uint32_t seed = 100;
    for (const Config& c : configs()) {
        const Albedo a = albedo(c.p, c.wo, n, seed++, true);
        char line[256];
        std::snprintf(line, sizeof line, "albedo %-48s %.4f ± %.4f", c.name.c_str(), a.mean, a.standard_error);
        test::report_measured(line);
        EXPECT_LE(a.mean, 1.0 + 0.005 + 3.0 * a.standard_error) << c.name;
        // Energy compensation (bsdf/albedo.h): an opaque white material loses
        // nothing, the smooth metals of roughness 0.1 at grazing views included.
        // A coloured sheen takes its largest channel's share from every channel below (glTF's albedo scaling).
        const bool white_sheen = c.p.sheen_color == vec3(0.0f) || c.p.sheen_color == vec3(1.0f);
        if (c.p.transmission == 0.0f && c.p.base_color == vec3(1.0f) && c.p.specular_color == vec3(1.0f) &&
            white_sheen)
            EXPECT_NEAR(a.mean, 1.0, 0.005 + 3.0 * a.standard_error) << c.name;
    }
    // A rough clear glass (bsdf/albedo.h's glass tables) loses nothing either,
    // from outside and inside, at every roughness and ior: 0.93 at a grazing
    // view at roughness 0.3 before its single scattering was made whole.
    double worst_glass = 0.0;
    for (float r : {0.05f, 0.1f, 0.2f, 0.3f, 0.5f, 0.7f, 1.0f})
        for (float ior : {1.33f, 1.5f, 2.0f})
            for (float c : {1.0f, 0.6f, 0.2f, 0.05f, -1.0f, -0.6f, -0.2f, -0.05f}) {
                const Albedo g = albedo(material(vec3(1.0f), 0.0f, r, 1.0f, ior), direction_at(c), 50000, seed++, true);
                worst_glass = std::max(worst_glass, std::fabs(g.mean - 1.0));
                EXPECT_NEAR(g.mean, 1.0, 0.01 + 3.0 * g.standard_error) << "rough glass r" << r << " ior " << ior
                                                                        << " wo.z " << c;
            }
    test::report_measured("albedo rough glass, r 0.05-1, ior 1.33-2, from both sides: largest |1 - albedo| " +
                          std::to_string(worst_glass));
    // Lossless Dirac interfaces: all the energy, reflected plus transmitted.
    const BsdfParams glass = material(vec3(1.0f), 0.0f, 0.0f, 1.0f, 1.5f);
    const BsdfParams mirror = material(vec3(1.0f), 1.0f, 0.0f);
    const BsdfParams pane = thin(glass);
    // From inside, |wo.z| 0.9 and 0.8 refract; 0.6 and 0.05 lie past the critical angle.
    for (float c : {1.0f, 0.6f, 0.05f, -1.0f, -0.9f, -0.8f, -0.6f, -0.05f}) {
        const Albedo g = albedo(glass, direction_at(c), n, seed++, true);
        test::report_measured("albedo smooth glass wo.z " + std::to_string(c) + ": " + std::to_string(g.mean));
        EXPECT_NEAR(g.mean, 1.0, 0.01) << "glass wo.z " << c;
        if (c > 0.0f) {
            const Albedo t = albedo(pane, direction_at(c), n, seed++, false);
            test::report_measured("albedo thin pane wo.z " + std::to_string(c) + ": " + std::to_string(t.mean));
            EXPECT_NEAR(t.mean, 1.0, 1e-5) << "thin pane wo.z " << c;
            const Albedo m = albedo(mirror, direction_at(c), n, seed++, true);
            test::report_measured("albedo white mirror wo.z " + std::to_string(c) + ": " + std::to_string(m.mean));
            EXPECT_NEAR(m.mean, 1.0, 0.01) << "mirror wo.z " << c;
        }
    }
}

TEST(Bsdf, DeltaLobesReflectAndRefractExactly) {
    std::mt19937 rng(11);
    const BsdfParams mirror = material(vec3(0.9f, 0.6f, 0.3f), 1.0f, 0.0f);
    ASSERT_TRUE(wf_device::bsdf_is_delta(&mirror));
    for (int k = 0; k < 1000; ++k) {
        vec3 wo = random_unit(rng);
        wo.z = std::fabs(wo.z);
        if (wo.z == 0.0f) continue;
        const BsdfSample s = wf_device::bsdf_sample(&mirror, wo, uniforms(rng));
        ASSERT_EQ(s.delta, 1);
        ASSERT_EQ(s.wi, vec3(-wo.x, -wo.y, wo.z));
        const vec3 weight = s.f * std::fabs(s.wi.z) / s.pdf;
        const vec3 fresnel = wf_device::fresnel_schlick(mirror.base_color, wo.z);
        for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(weight[ch], fresnel[ch], 1e-5f * fresnel[ch]);
    }
    // A smooth thin pane: light goes straight through, or is mirrored.
    const BsdfParams pane = thin(material(vec3(0.9f, 0.8f, 0.7f), 0.0f, 0.0f, 1.0f, 1.5f));
    ASSERT_TRUE(wf_device::bsdf_is_delta(&pane));
    int through = 0;
    for (int k = 0; k < 1000; ++k) {
        vec3 wo = random_unit(rng);
        wo.z = std::fabs(wo.z);
        if (wo.z == 0.0f) continue;
        const BsdfSample s = wf_device::bsdf_sample(&pane, wo, uniforms(rng));
        ASSERT_EQ(s.delta, 1);
        ASSERT_TRUE(s.wi == -wo || s.wi == vec3(-wo.x, -wo.y, wo.z));
        through += s.wi == -wo;
    }
    EXPECT_GT(through, 600); // measured 778: Schlick averages 0.2 over uniformly drawn wo
    const BsdfParams glass = material(vec3(1.0f), 0.0f, 0.0f, 1.0f, 1.5f);
    ASSERT_TRUE(wf_device::bsdf_is_delta(&glass));
    const float critical = std::sqrt(1.0f - 1.0f / (1.5f * 1.5f)); // |cos theta| at the critical angle, inside
    int refracted = 0, reflected = 0, tir = 0;
    for (int k = 0; k < 20000; ++k) {
        const vec3 wo = random_unit(rng);
        if (wo.z == 0.0f) continue;
        const BsdfSample s = wf_device::bsdf_sample(&glass, wo, uniforms(rng));
        ASSERT_EQ(s.delta, 1);
        ASSERT_GT(s.pdf, 0.0f);
        const float sin_o = std::hypot(wo.x, wo.y), sin_i = std::hypot(s.wi.x, s.wi.y);
        const float n_o = side_index(glass, wo), n_i = side_index(glass, s.wi);
        if (wo.z < 0.0f && -wo.z < critical) {
            ++tir;
            ASSERT_LT(s.wi.z, 0.0f) << "no total internal reflection at cos " << wo.z;
            ASSERT_NEAR(s.f.x * std::fabs(s.wi.z) / s.pdf, 1.0f, 1e-5f);
        }
        if (s.wi.z * wo.z < 0.0f) {
            ++refracted;
            ASSERT_NEAR(n_o * sin_o, n_i * sin_i, 1e-5f) << "Snell";
            if (sin_o > 1e-3f) ASSERT_LT(glm::dot(glm::vec2(wo.x, wo.y), glm::vec2(s.wi.x, s.wi.y)), 0.0f);
            ASSERT_NEAR(glm::length(s.wi), 1.0f, 1e-5f);
        } else {
            ++reflected;
            ASSERT_EQ(s.wi, vec3(-wo.x, -wo.y, wo.z));
        }
    }
    test::report_measured("smooth glass: " + std::to_string(refracted) + " refracted, " + std::to_string(reflected) +
                          " reflected, of which " + std::to_string(tir) + " past the critical angle");
    EXPECT_GT(tir, 1000);
    EXPECT_GT(refracted, 10000);
}

bool finite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(Bsdf, NoNanOrInfAtAnyRoughness) {
    const float threshold = std::sqrt(WF_BSDF_DELTA_ALPHA); // roughness at the Dirac limit
    const std::vector<float> roughness = {0.0f, 1e-4f, 1e-3f, threshold * 0.999f, threshold, threshold * 1.001f,
                                          0.01f, 0.05f, 1.0f};
    std::vector<BsdfParams> materials;
    for (float r : roughness) {
        materials.push_back(material(vec3(0.8f), 1.0f, r));
        materials.push_back(material(vec3(0.8f), 0.0f, r));
        materials.push_back(material(vec3(1.0f), 0.0f, r, 1.0f, 1.5f));
        materials.push_back(material(vec3(0.7f), 0.2f, r, 0.5f, 1.33f));
        materials.push_back(thin(material(vec3(0.9f), 0.0f, r, 0.8f, 1.5f)));
        materials.push_back(coated(material(vec3(0.8f), 0.0f, 0.5f), 1.0f, r));
        materials.push_back(coated(material(vec3(1.0f), 0.0f, r, 1.0f, 1.5f), 0.7f, r));
        materials.push_back(sheened(material(vec3(0.5f), 0.0f, 0.8f), vec3(1.0f), r));
    }
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> pick(0.0f, 1.0f);
    const std::vector<vec3> special = {vec3(0, 0, 1), vec3(0, 0, -1), direction_at(0.05f), direction_at(-0.05f),
                                       direction_at(1e-4f), direction_at(-1e-4f), direction_at(1e-7f)};
    int samples = 0;
    double largest_weight = 0.0;
    for (int k = 0; k < 100000; ++k) {
        const BsdfParams& p = materials[k % materials.size()];
        vec3 wo = (k / materials.size()) % 2 ? special[(k / 2) % special.size()] : random_unit(rng);
        if (outside_only(p)) wo.z = std::fabs(wo.z);
        const BsdfSample s = wf_device::bsdf_sample(&p, wo, uniforms(rng));
        ASSERT_TRUE(finite(s.wi) && finite(s.f) && std::isfinite(s.pdf)) << "roughness " << p.roughness;
        ASSERT_GE(s.pdf, 0.0f);
        if (s.pdf > 0.0f) {
            ++samples;
            const vec3 w = s.f * std::fabs(s.wi.z) / s.pdf;
            ASSERT_TRUE(finite(w)) << "roughness " << p.roughness << " wo.z " << wo.z;
            largest_weight = std::max(largest_weight, double(std::max(w.x, std::max(w.y, w.z))));
            if (!s.delta) {
                ASSERT_TRUE(finite(wf_device::bsdf_eval(&p, wo, s.wi)));
                ASSERT_TRUE(std::isfinite(wf_device::bsdf_pdf(&p, wo, s.wi)));
            }
        }
        const vec3 wi = random_unit(rng);
        const vec3 f = wf_device::bsdf_eval(&p, wo, wi);
        ASSERT_TRUE(finite(f)) << "roughness " << p.roughness;
        // Layers weighed by what those above leave (coat, sheen) must never go negative.
        ASSERT_GE(std::min(f.x, std::min(f.y, f.z)), 0.0f) << "roughness " << p.roughness << " wo.z " << wo.z;
        ASSERT_TRUE(std::isfinite(wf_device::bsdf_pdf(&p, wo, wi))) << "roughness " << p.roughness;
    }
    test::report_measured("no NaN/Inf: " + std::to_string(samples) + " samples, largest weight f|cos|/pdf " +
                          std::to_string(largest_weight));
    // Every lobe, the sheen's included (41 when the cosine sampled it).
    EXPECT_LT(largest_weight, 10.0);
}

// ---------------------------------------------------------------------------
// The same header compiled by PoCL for the device gives the host's results.

const char* const kBsdfKernel = R"CLC(
__kernel void bsdf_probe(__global const float* in, __global float* out) {
    const uint i = get_global_id(0);
    __global const float* a = in + 23 * i;
    BsdfParams p;
    p.base_color = (float3)(a[0], a[1], a[2]);
    p.metallic = a[3];
    p.roughness = a[4];
    p.transmission = a[5];
    p.ior = a[6];
    p.specular = 1.0f;
    p.specular_color = (float3)(a[17], 1.0f, 1.0f);
    p.thin_walled = (uint)a[18];
    p.clearcoat = a[19];
    p.clearcoat_roughness = a[20];
    p.sheen_color = (float3)(a[21], 0.5f * a[21], a[21]);
    p.sheen_roughness = a[22];
    p.hemisphere = (uint)a[7];
    const float3 wo = (float3)(a[8], a[9], a[10]);
    const float3 wi = (float3)(a[11], a[12], a[13]);
    const float3 u = (float3)(a[14], a[15], a[16]);
    __global float* o = out + 14 * i;
    const float3 f = bsdf_eval(&p, wo, wi);
    o[0] = f.x; o[1] = f.y; o[2] = f.z;
    o[3] = bsdf_pdf(&p, wo, wi);
    const BsdfSample s = bsdf_sample(&p, wo, u);
    o[4] = s.wi.x; o[5] = s.wi.y; o[6] = s.wi.z;
    o[7] = s.f.x; o[8] = s.f.y; o[9] = s.f.z;
    o[10] = s.pdf;
    o[11] = (float)s.delta;
    o[12] = (float)bsdf_is_delta(&p);
    o[13] = 0.0f;
}
)CLC";

TEST(Bsdf, DeviceMatchesHost) {
    const cl::Program program = test::build_test_program(expand_kernel_source("bsdf/bsdf.h") + kBsdfKernel);
    const std::vector<BsdfParams> materials = {
        material(vec3(0.8f, 0.5f, 0.2f), 0.0f, 0.5f), material(vec3(0.9f), 1.0f, 0.3f),
        material(vec3(1.0f), 0.0f, 0.3f, 1.0f, 1.5f), material(vec3(1.0f), 0.0f, 0.0f, 1.0f, 1.33f),
        material(vec3(0.7f), 0.3f, 0.6f, 0.5f, 1.5f, WF_HEMISPHERE_UNIFORM), material(vec3(0.9f), 1.0f, 0.0f),
        thin(material(vec3(0.8f), 0.0f, 0.4f, 0.7f, 1.5f)), thin(material(vec3(1.0f), 0.0f, 0.0f, 1.0f, 1.5f)),
        [] {
            BsdfParams p = material(vec3(0.6f), 0.0f, 0.5f, 0.5f, 1.5f);
            p.specular_color = vec3(1.7f, 1.0f, 1.0f);
            return p;
        }(),
        coated(material(vec3(0.7f), 0.0f, 0.5f), 1.0f, 0.3f), coated(material(vec3(0.9f), 1.0f, 0.2f), 0.6f, 0.0f),
        coated(material(vec3(1.0f), 0.0f, 0.2f, 1.0f, 1.5f), 1.0f, 0.4f),
        sheened(material(vec3(0.6f), 0.0f, 0.7f), vec3(0.8f, 0.4f, 0.8f), 0.4f),
        coated(sheened(material(vec3(0.9f), 1.0f, 0.3f), vec3(1.0f, 0.5f, 1.0f), 0.1f), 0.5f, 0.0f),
    };
    std::mt19937 rng(5);
    const size_t n = 600;
    constexpr size_t kRow = 23;
    std::vector<float> in(kRow * n);
    for (size_t i = 0; i < n; ++i) {
        const BsdfParams& p = materials[i % materials.size()];
        vec3 wo = random_unit(rng), wi = random_unit(rng);
        if (outside_only(p)) wo.z = std::fabs(wo.z);
        const vec3 u = uniforms(rng);
        const float row[kRow] = {p.base_color.x, p.base_color.y, p.base_color.z, p.metallic, p.roughness,
                                 p.transmission, p.ior, float(p.hemisphere), wo.x, wo.y, wo.z, wi.x, wi.y, wi.z,
                                 u.x, u.y, u.z, p.specular_color.x, float(p.thin_walled), p.clearcoat,
                                 p.clearcoat_roughness, p.sheen_color.x, p.sheen_roughness};
        std::copy(row, row + kRow, in.begin() + kRow * i);
    }
    const OpenClDevice& device = test::cpu_device();
    cl::Buffer input(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, in.size() * sizeof(float), in.data());
    cl::Buffer output(device.context, CL_MEM_WRITE_ONLY, 14 * n * sizeof(float));
    cl::Kernel kernel(program, "bsdf_probe");
    kernel.setArg(0, input);
    kernel.setArg(1, output);
    device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(n), cl::NullRange);
    std::vector<float> out(14 * n);
    device.queue.enqueueReadBuffer(output, CL_TRUE, 0, out.size() * sizeof(float), out.data());

    auto close = [](float a, float b) { return std::fabs(a - b) <= 1e-3f * std::max(std::fabs(a), std::fabs(b)) + 1e-6f; };
    int mismatches = 0, nonzero_samples = 0;
    for (size_t i = 0; i < n; ++i) {
        const float* a = &in[kRow * i];
        BsdfParams p = material(vec3(a[0], a[1], a[2]), a[3], a[4], a[5], a[6], uint32_t(a[7]));
        p.specular_color.x = a[17];
        p.thin_walled = uint32_t(a[18]);
        p.clearcoat = a[19];
        p.clearcoat_roughness = a[20];
        p.sheen_color = vec3(a[21], 0.5f * a[21], a[21]);
        p.sheen_roughness = a[22];
        const vec3 wo(a[8], a[9], a[10]), wi(a[11], a[12], a[13]), u(a[14], a[15], a[16]);
        const vec3 f = wf_device::bsdf_eval(&p, wo, wi);
        const BsdfSample s = wf_device::bsdf_sample(&p, wo, u);
        const float host[13] = {f.x, f.y, f.z, wf_device::bsdf_pdf(&p, wo, wi), s.wi.x, s.wi.y, s.wi.z,
                                s.f.x, s.f.y, s.f.z, s.pdf, float(s.delta), float(wf_device::bsdf_is_delta(&p))};
        nonzero_samples += s.pdf > 0.0f;
        bool same = true;
        for (int k = 0; k < 13; ++k) same = same && close(host[k], out[14 * i + k]);
        if (!same) {
            ++mismatches;
            ADD_FAILURE() << "item " << i << " differs; host pdf " << host[10] << " device pdf " << out[14 * i + 10];
            if (mismatches > 5) break;
        }
    }
    test::report_measured("device vs host: " + std::to_string(n) + " items (" + std::to_string(nonzero_samples) +
                          " successful samples), " + std::to_string(mismatches) + " differ beyond 1e-3");
    EXPECT_EQ(mismatches, 0);
}

} // namespace
} // namespace wf
