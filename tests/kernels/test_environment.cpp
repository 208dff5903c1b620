// test_environment.cpp — the environment light (kernels/lights/environment.h,
// host/scene/environment_map.h): its sampler against its own density by a
// chi-square test, the density's normalisation, a constant map, an irradiance
// estimate against exact quadrature, the device against the host, the files
// it must refuse, and when a scene gets the default environment.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "scene/environment_map.h"
#include "base/errors.h"
#include "device/device_buffer.h"
#include "device/kernel_sources.h"
#include "device/layout_check.h"
#include "lights/environment.h"
#include "support/statistics.h"
#include "support/test_support.h"

namespace wf {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

Image blank(uint32_t w, uint32_t h) { return Image{w, h, std::vector<float>(size_t{w} * h * 3, 0.0f), {}}; }

void set(Image& image, uint32_t x, uint32_t y, float r, float g, float b) {
    float* p = &image.rgb[3 * (size_t{y} * image.width + x)];
    p[0] = r, p[1] = g, p[2] = b;
}

// A dim sky with a sun of 3x2 texels some 10^5 times brighter, above the horizon.
Image sun_map() {
    Image image = blank(64, 32);
    for (uint32_t y = 0; y < 32; ++y)
        for (uint32_t x = 0; x < 64; ++x) set(image, x, y, 0.05f, 0.06f, 0.08f);
    for (uint32_t y = 9; y < 11; ++y)
        for (uint32_t x = 20; x < 23; ++x) set(image, x, y, 6000.0f, 5000.0f, 4000.0f);
    return image;
}

// Colour gradients in both directions, bright at the poles' rows too.
Image gradient_map() {
    Image image = blank(64, 32);
    for (uint32_t y = 0; y < 32; ++y)
        for (uint32_t x = 0; x < 64; ++x) set(image, x, y, (x + 1) / 64.0f, (32 - y) / 8.0f, 0.1f + (y % 5));
    return image;
}

// Whole rows of zero (at both poles and across the middle), the rest uneven.
Image zero_rows_map() {
    Image image = blank(64, 32);
    for (uint32_t y = 0; y < 32; ++y) {
        if (y < 3 || (y >= 12 && y < 15) || y >= 29) continue;
        for (uint32_t x = 0; x < 64; ++x) {
            const float v = float((x * 7 + y * 13) % 11) * (x % 9 == 0 ? 0.0f : 1.0f);
            set(image, x, y, v, 0.5f * v, 2.0f * v);
        }
    }
    return image;
}

struct Case {
    std::string name;
    EnvironmentMap map;
};

std::vector<Case> cases() {
    return {{"sun", make_environment(sun_map(), 1.5f, 50.0f, "sun")},
            {"gradient", make_environment(gradient_map(), 1.0f, -120.0f, "gradient")},
            {"zero rows", make_environment(zero_rows_map(), 1.0f, 90.0f, "zero rows")},
            {"constant", constant_environment(1.0f)}};
}

wf_device::EnvironmentSample sample(const EnvironmentMap& m, float u0, float u1) {
    return wf_device::environment_sample(m.header, m.texels.data(), m.distribution.data(),
                                         wf_device::make_float2(u0, u1));
}

float pdf(const EnvironmentMap& m, glm::vec3 d) { return wf_device::environment_pdf(m.header, m.texels.data(), d); }

glm::vec3 direction(double theta, double phi) { // the world's (theta, phi) as the map frame defines them
    return glm::vec3(float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)),
                     float(-std::sin(theta) * std::cos(phi)));
}

// The probability of each cell of an nt x np grid over world (theta, phi),
// exactly: the density is constant over a texel, so each cell is summed over
// its overlaps with texels, environment_pdf taken at each overlap's centre.
std::vector<double> cell_probabilities(const EnvironmentMap& m, int nt, int np) {
    const Environment& e = m.header;
    const bool constant = e.flags & WF_ENVIRONMENT_CONSTANT;
    const uint32_t w = constant ? 1 : e.width, h = constant ? 1 : e.height;
    const double rotation = std::atan2(double(e.sin_rotation), double(e.cos_rotation)); // world phi = map phi - a
    std::vector<double> p(size_t(nt) * np, 0.0);
    for (int i = 0; i < nt; ++i)
        for (int j = 0; j < np; ++j) {
            const double t0 = kPi * i / nt, t1 = kPi * (i + 1) / nt;
            const double f0 = 2 * kPi * j / np - kPi, f1 = 2 * kPi * (j + 1) / np - kPi;
            for (uint32_t y = 0; y < h; ++y) {
                const double a = std::max(t0, kPi * y / h), b = std::min(t1, kPi * (y + 1) / h);
                if (b <= a) continue;
                for (uint32_t x = 0; x < w; ++x)
                    for (int k = -1; k <= 1; ++k) {
                        const double c = 2 * kPi * x / w - kPi - rotation + 2 * kPi * k;
                        const double lo = std::max(f0, c), hi = std::min(f1, c + 2 * kPi / w);
                        if (hi <= lo) continue;
                        const double dens = pdf(m, direction(0.5 * (a + b), 0.5 * (lo + hi)));
                        p[size_t(i) * np + j] += dens * (std::cos(a) - std::cos(b)) * (hi - lo);
                    }
            }
        }
    return p;
}

TEST(EnvironmentStatistics, ChiSquarePValueMatchesTables) {
    EXPECT_NEAR(test::regularized_gamma_q(1.0, 2.0), std::exp(-2.0), 1e-12);
    EXPECT_NEAR(test::regularized_gamma_q(5.0, 0.5 * 18.307), 0.05, 1e-4);   // chi2(10) at 95%
    EXPECT_NEAR(test::regularized_gamma_q(50.0, 0.5 * 124.342), 0.05, 1e-4); // chi2(100)
    EXPECT_NEAR(test::regularized_gamma_q(2.5, 0.5 * 0.554), 0.99, 1e-3);    // chi2(5) at 1%
}

// (1) Samples binned over the sphere agree with the density integrated per cell.
TEST(EnvironmentSampling, ChiSquareAgainstPdf) {
    const int nt = 21, np = 37; // not aligned with the 32 x 64 texels
    const size_t n = 1000000;
    for (const Case& c : cases()) {
        const std::vector<double> probability = cell_probabilities(c.map, nt, np);
        double total = 0.0;
        for (double p : probability) total += p;
        EXPECT_NEAR(total, 1.0, 1e-5) << c.name;
        std::vector<double> observed(probability.size(), 0.0), expected(probability.size());
        for (size_t i = 0; i < probability.size(); ++i) expected[i] = probability[i] * n;
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        size_t unusable = 0;
        for (size_t s = 0; s < n; ++s) {
            const auto es = sample(c.map, uniform(rng), uniform(rng));
            if (!(es.pdf > 0.0f)) {
                ++unusable;
                continue;
            }
            const double theta = std::acos(std::clamp(double(es.direction.y), -1.0, 1.0));
            const double phi = std::atan2(double(es.direction.x), -double(es.direction.z));
            const int i = std::min(nt - 1, int(theta / kPi * nt));
            const int j = std::min(np - 1, std::max(0, int((phi + kPi) / (2 * kPi) * np)));
            observed[size_t(i) * np + j] += 1.0;
        }
        const double p_value = test::chi_square_test(observed, expected).p_value;
        test::report_measured("environment chi-square " + c.name + ": p = " + std::to_string(p_value) +
                              ", unusable samples " + std::to_string(unusable));
        EXPECT_GT(p_value, 0.01 / 4) << c.name; // Šidák-like split of 1% over the four maps
        EXPECT_LT(unusable, n / 100000) << c.name;
    }
}

// (2) The density integrates to 1 over the sphere, by a fine midpoint rule in
// (cos theta, phi) that knows nothing of the texels.
TEST(EnvironmentSampling, PdfIntegratesToOne) {
    const int nz = 1000, np = 2000;
    for (const Case& c : cases()) {
        if (c.name == "sun") continue; // its edges need the exact sum above (checked there)
        double sum = 0.0;
        for (int i = 0; i < nz; ++i) {
            const double z = 1.0 - 2.0 * (i + 0.5) / nz, r = std::sqrt(1.0 - z * z);
            for (int j = 0; j < np; ++j) {
                const double phi = 2 * kPi * (j + 0.5) / np;
                sum += pdf(c.map, glm::vec3(float(r * std::sin(phi)), float(z), float(-r * std::cos(phi))));
            }
        }
        const double integral = sum * 4.0 * kPi / (double(nz) * np);
        test::report_measured("environment pdf integral " + c.name + ": " + std::to_string(integral));
        EXPECT_NEAR(integral, 1.0, 2e-3) << c.name;
    }
}

// (3) A constant map, through the texel path and as the constant environment:
// density 1 / 4pi everywhere, radiance exactly the texel times the scale.
TEST(EnvironmentSampling, ConstantMapIsUniform) {
    Image image = blank(48, 24);
    for (uint32_t y = 0; y < 24; ++y)
        for (uint32_t x = 0; x < 48; ++x) set(image, x, y, 2.5f, 2.5f, 2.5f);
    const EnvironmentMap maps[] = {make_environment(image, 3.0f, 30.0f, "constant"), constant_environment(7.5f)};
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    double worst = 0.0;
    for (const EnvironmentMap& m : maps)
        for (int s = 0; s < 10000; ++s) {
            const auto es = sample(m, uniform(rng), uniform(rng));
            EXPECT_NEAR(glm::length(es.direction), 1.0f, 1e-5f);
            worst = std::max(worst, std::fabs(es.pdf * 4.0 * kPi - 1.0));
            ASSERT_EQ(es.radiance, glm::vec3(7.5f));
        }
    test::report_measured("environment constant map: largest |4 pi pdf - 1| = " + std::to_string(worst));
    EXPECT_LT(worst, 1e-5);
}

// A black map keeps every direction reachable by sampling the sphere by
// solid angle: its density is 1/(4 pi) everywhere, as for the constant map.
TEST(EnvironmentSampling, BlackMapIsSampledUniformly) {
    const EnvironmentMap m = make_environment(blank(16, 8), 1.0f, 0.0f, "black");
    ASSERT_EQ(m.warnings.size(), 1u);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int s = 0; s < 1000; ++s) EXPECT_NEAR(sample(m, uniform(rng), uniform(rng)).pdf * 4.0 * kPi, 1.0, 1e-5);
}

// (4) Irradiance on an upward-facing plane by importance sampling, against the
// exact sum over texels of L * integral of cos theta over the texel.
TEST(EnvironmentSampling, IrradianceMatchesQuadrature) {
    for (const Case& c : cases()) {
        if (c.name == "constant") continue;
        const EnvironmentMap& m = c.map;
        const uint32_t w = m.header.width, h = m.header.height;
        glm::dvec3 exact(0.0);
        for (uint32_t y = 0; y < h; ++y) {
            const double z0 = std::max(0.0, std::cos(kPi * y / h)), z1 = std::max(0.0, std::cos(kPi * (y + 1) / h));
            for (uint32_t x = 0; x < w; ++x) {
                const float* t = &m.texels[4 * (size_t{y} * w + x)];
                exact += glm::dvec3(t[0], t[1], t[2]) * double(m.header.scale[0]) * (2 * kPi / w) * 0.5 *
                         (z0 * z0 - z1 * z1);
            }
        }
        const size_t n = 200000;
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        glm::dvec3 sum(0.0), sum2(0.0);
        for (size_t s = 0; s < n; ++s) {
            const auto es = sample(m, uniform(rng), uniform(rng));
            const glm::dvec3 f = es.pdf > 0.0f ? glm::dvec3(es.radiance) * std::max(0.0, double(es.direction.y)) / double(es.pdf)
                                               : glm::dvec3(0.0);
            sum += f;
            sum2 += f * f;
        }
        const glm::dvec3 mean = sum / double(n), sigma = glm::sqrt((sum2 / double(n) - mean * mean) / double(n));
        for (int k = 0; k < 3; ++k) {
            const double z = std::fabs(mean[k] - exact[k]) / sigma[k];
            test::report_measured("environment irradiance " + c.name + " channel " + std::to_string(k) +
                                  ": estimate " + std::to_string(mean[k]) + ", exact " + std::to_string(exact[k]) +
                                  ", z = " + std::to_string(z));
            EXPECT_LT(z, 3.0) << c.name << " channel " << k;
        }
    }
}

// The rotation turns the map about +y: the sun's texel seen from R_y(a) d.
TEST(EnvironmentSampling, RotationTurnsTheMapAboutUp) {
    const EnvironmentMap m = make_environment(sun_map(), 1.0f, 90.0f, "sun");
    const double theta = kPi * 10.0 / 32.0, phi = 2 * kPi * 21.5 / 64.0 - kPi; // the sun's centre, map frame
    const glm::vec3 d = direction(theta, phi);
    const glm::vec3 turned(d.z, d.y, -d.x); // R_y(90 degrees)
    EXPECT_EQ(wf_device::environment_radiance(m.header, m.texels.data(), turned).x, 6000.0f);
    EXPECT_EQ(wf_device::environment_radiance(m.header, m.texels.data(), d).x, 0.05f);
}

const char* kEnvironmentKernel = R"(
__kernel void environment_test(Environment env, __global const float* texels,
                               __global const float* distribution, __global const float* u,
                               __global float* out) {
    const uint i = get_global_id(0);
    const EnvironmentSample s = environment_sample(env, texels, distribution, (float2)(u[2 * i], u[2 * i + 1]));
    __global float* o = out + 9 * i;
    o[0] = s.direction.x; o[1] = s.direction.y; o[2] = s.direction.z;
    o[3] = s.radiance.x; o[4] = s.radiance.y; o[5] = s.radiance.z;
    o[6] = s.pdf;
    o[7] = environment_pdf(env, texels, s.direction);
    o[8] = environment_radiance(env, texels, s.direction).x;
}
)";

// (5) The device compiles the same header and agrees with the host.
TEST(EnvironmentDevice, AgreesWithHost) {
    const OpenClDevice& device = test::cpu_device();
    const cl::Program program = test::build_test_program(expand_kernel_source("lights/environment.h") + kEnvironmentKernel);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const size_t n = 400;
    std::vector<float> u(2 * n);
    for (float& v : u) v = uniform(rng);
    u[0] = 0.0f, u[1] = 0.0f, u[2] = 0.99999994f, u[3] = 0.99999994f; // the ends of [0, 1)
    for (const Case& c : cases()) {
        size_t bytes = 0;
        const cl::Buffer texels = upload_read_only(device.context, c.map.texels, bytes);
        const cl::Buffer distribution = upload_read_only(device.context, c.map.distribution, bytes);
        cl::Buffer ub(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, u.size() * sizeof(float), u.data());
        cl::Buffer out(device.context, CL_MEM_WRITE_ONLY, 9 * n * sizeof(float));
        cl::Kernel kernel(program, "environment_test");
        kernel.setArg(0, sizeof(Environment), &c.map.header);
        kernel.setArg(1, texels);
        kernel.setArg(2, distribution);
        kernel.setArg(3, ub);
        kernel.setArg(4, out);
        device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(n));
        std::vector<float> o(9 * n);
        device.queue.enqueueReadBuffer(out, CL_TRUE, 0, o.size() * sizeof(float), o.data());
        size_t other_texel = 0;
        float worst_direction = 0.0f;
        for (size_t i = 0; i < n; ++i) {
            const float* g = &o[9 * i];
            const auto h = sample(c.map, u[2 * i], u[2 * i + 1]);
            worst_direction = std::max(worst_direction, glm::length(glm::vec3(g[0], g[1], g[2]) - h.direction));
            EXPECT_EQ(g[6], g[7]) << c.name << ": device sample pdf differs from its environment_pdf";
            EXPECT_EQ(g[3], g[8]) << c.name;
            if (g[6] != h.pdf || g[3] != h.radiance.x) ++other_texel; // rounding across a texel edge
        }
        test::report_measured("environment device " + c.name + ": largest direction difference " +
                              std::to_string(worst_direction) + ", samples in another texel " +
                              std::to_string(other_texel) + " of " + std::to_string(n));
        EXPECT_LT(worst_direction, 1e-5f) << c.name;
        EXPECT_LE(other_texel, n / 100) << c.name;
    }
}

struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& test)
        : path(fs::temp_directory_path() / ("wf_environment_" + std::to_string(getpid()) + "_" + test)) {
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

void write_raw(const std::string& path, int w, int h, int channels, OIIO::TypeDesc type, const void* data) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, channels, type)));
    ASSERT_TRUE(out->write_image(type, data));
    ASSERT_TRUE(out->close());
}

void expect_input_error(const std::string& path, const std::string& why) {
    try {
        load_environment(path);
        ADD_FAILURE() << path << " was accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_NE(message.find(why), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

// (6) Files it must refuse, each with one line naming the file.
TEST(EnvironmentFiles, BadFilesAreRefusedByName) {
    TempDir dir("bad");
    expect_input_error((dir.path / "missing.exr").string(), "environment map: no such file");

    const std::vector<unsigned char> two(8 * 4 * 2, 128);
    const std::string png = (dir.path / "grey_alpha.png").string();
    write_raw(png, 8, 4, 2, OIIO::TypeDesc::UINT8, two.data());
    expect_input_error(png, "2 channels");

    const std::vector<unsigned char> rgb(8 * 4 * 3, 128);
    const std::string ldr = (dir.path / "ldr.png").string();
    write_raw(ldr, 8, 4, 3, OIIO::TypeDesc::UINT8, rgb.data());
    expect_input_error(ldr, "not linear float");

    std::vector<float> texels(8 * 4 * 3, 1.0f);
    texels[3 * 13 + 1] = std::nanf("");
    const std::string nan = (dir.path / "nan.exr").string();
    write_raw(nan, 8, 4, 3, OIIO::TypeDesc::FLOAT, texels.data());
    expect_input_error(nan, "texel (5, 1) is NaN");
}

TEST(EnvironmentFiles, LoadsExrAndClampsNegativeTexels) {
    TempDir dir("good");
    std::vector<float> texels(8 * 4 * 3, 1.0f);
    texels[3 * 9] = -0.5f;
    const std::string path = (dir.path / "sky.exr").string();
    write_raw(path, 8, 4, 3, OIIO::TypeDesc::FLOAT, texels.data());
    const EnvironmentMap m = load_environment(path, 2.0f, 0.0f);
    EXPECT_EQ(m.header.width, 8u);
    EXPECT_EQ(m.header.height, 4u);
    EXPECT_EQ(m.header.scale[1], 2.0f);
    EXPECT_EQ(m.texels[4 * 9], 0.0f);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_NE(m.warnings[0].find("1 negative"), std::string::npos) << m.warnings[0];
}

} // namespace
} // namespace wf

namespace wf {
namespace {

// The Environment struct, passed by value to kernels, has the same layout on
// the device (with every other shared struct).
TEST(EnvironmentDevice, SharedLayoutsAgree) { EXPECT_NO_THROW(check_shared_layouts(test::cpu_device())); }

// A scene is lit by the default environment when it has no light, or when its
// only light is emission from textures (glowing details, as DamagedHelmet's),
// and says why; an untextured emitter or a punctual light keeps it dark.
TEST(DefaultLight, OnlyForScenesWithoutALightOrLitByTexturesAlone) {
    auto scene_with = [](bool emits, bool textured, bool punctual) {
        Scene scene;
        SceneMaterial m;
        if (emits) m.emission = glm::vec3(2.0f);
        if (textured) m.textures[WF_TEXTURE_EMISSIVE].texture = 0;
        scene.materials = {m};
        scene.triangle_material = {0};
        if (punctual) {
            scene.punctual_lights.emplace_back();
            scene.punctual_lights.back().intensity[0] = 1.0f;
        }
        light_unlit_scene(scene);
        return scene;
    };
    const Scene unlit = scene_with(false, false, false);
    ASSERT_TRUE(unlit.environment);
    ASSERT_EQ(unlit.warnings.size(), 1u);
    EXPECT_NE(unlit.warnings[0].find("has no light"), std::string::npos);

    const Scene textured = scene_with(true, true, false);
    ASSERT_TRUE(textured.environment);
    ASSERT_EQ(textured.warnings.size(), 1u);
    EXPECT_NE(textured.warnings[0].find("emission from textures"), std::string::npos) << textured.warnings[0];

    EXPECT_FALSE(scene_with(true, false, false).environment);
    EXPECT_FALSE(scene_with(true, true, true).environment);
    EXPECT_FALSE(scene_with(false, false, true).environment);
}

} // namespace
} // namespace wf
