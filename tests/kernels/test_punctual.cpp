// test_punctual.cpp — glTF punctual lights (kernels/lights/punctual.h,
// host/gltf/gltf_lights.h): irradiance from each kind against its closed form,
// the spot's cone falloff, and parsing from a glTF file.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "base/errors.h"
#include "gltf/gltf_lights.h"
#include "device/kernel_sources.h"
#include "lights/punctual.h"
#include "support/test_support.h"

namespace wf {
namespace {

constexpr double kPi = 3.14159265358979323846;

PunctualLight light(uint32_t type, glm::vec3 position, glm::vec3 direction, float intensity) {
    PunctualLight l{};
    l.type = type;
    for (int k = 0; k < 3; ++k) {
        l.position[k] = position[k];
        l.direction[k] = direction[k];
        l.intensity[k] = intensity * (k + 1);
    }
    l.cos_inner = 1.0f;
    l.cos_outer = -1.0f;
    return l;
}

// Irradiance on the plane y = 0 (normal +y) at `p`: Li |cos theta|.
glm::vec3 irradiance(const PunctualLight& l, glm::vec3 p) {
    const wf_device::PunctualSample s = wf_device::punctual_sample(l, p);
    return s.Li * std::max(0.0f, s.direction.y);
}

TEST(PunctualLights, PointIrradianceIsIntensityCosOverDistanceSquared) {
    const glm::vec3 at(0.3f, 2.0f, -0.7f);
    const PunctualLight l = light(WF_PUNCTUAL_POINT, at, glm::vec3(0, -1, 0), 5.0f);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-4.0f, 4.0f);
    double worst = 0.0;
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 p(u(rng), 0.0f, u(rng));
        const glm::dvec3 d = glm::dvec3(at) - glm::dvec3(p);
        const double r2 = glm::dot(d, d), cos_theta = d.y / std::sqrt(r2);
        const glm::vec3 e = irradiance(l, p);
        const wf_device::PunctualSample s = wf_device::punctual_sample(l, p);
        EXPECT_NEAR(s.distance, std::sqrt(r2), 1e-5);
        for (int k = 0; k < 3; ++k) {
            const double expected = 5.0 * (k + 1) * cos_theta / r2;
            worst = std::max(worst, std::fabs(e[k] / expected - 1.0));
        }
    }
    test::report_measured("point light irradiance: largest relative error " + std::to_string(worst));
    EXPECT_LT(worst, 1e-5);
}

TEST(PunctualLights, SpotFalloffAtTheConeAngles) {
    PunctualLight l = light(WF_PUNCTUAL_SPOT, glm::vec3(0, 3, 0), glm::vec3(0, -1, 0), 2.0f);
    const double inner = 0.3, outer = 0.5;
    l.cos_inner = float(std::cos(inner));
    l.cos_outer = float(std::cos(outer));
    const auto at_angle = [&](double a) { // a point on the floor seen at angle a from the axis, at distance 1
        const glm::vec3 p(float(std::sin(a)), float(3.0 - std::cos(a)), 0.0f);
        return wf_device::punctual_sample(l, p).Li.x / 2.0f; // intensity 2 in red, distance 1
    };
    EXPECT_NEAR(at_angle(0.0), 1.0f, 1e-6f);
    EXPECT_NEAR(at_angle(inner - 1e-3), 1.0f, 1e-6f);
    EXPECT_NEAR(at_angle(outer + 1e-3), 0.0f, 1e-7f);
    EXPECT_NEAR(at_angle(1.5), 0.0f, 1e-7f);
    const double mid = std::acos(0.5 * (std::cos(inner) + std::cos(outer))); // t = 1/2, falloff 1/4
    EXPECT_NEAR(at_angle(mid), 0.25f, 1e-4f);
    test::report_measured("spot falloff at inner, mid-cosine, outer: " + std::to_string(at_angle(inner)) + ", " +
                          std::to_string(at_angle(mid)) + ", " + std::to_string(at_angle(outer)));
}

TEST(PunctualLights, DirectionalIrradianceIsLuxTimesCos) {
    const glm::vec3 travel = glm::normalize(glm::vec3(1.0f, -2.0f, 0.5f));
    const PunctualLight l = light(WF_PUNCTUAL_DIRECTIONAL, glm::vec3(9.0f), travel, 3.0f);
    const glm::vec3 p(1.0f, 0.0f, -5.0f);
    const wf_device::PunctualSample s = wf_device::punctual_sample(l, p);
    EXPECT_TRUE(std::isinf(s.distance));
    const glm::vec3 e = irradiance(l, p);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[k], 3.0f * (k + 1) * -travel.y, 1e-5f);
}

const char* kLightsGltf = R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"name": "bulb", "type": "point", "color": [1.0, 0.5, 0.25], "intensity": 8.0},
    {"name": "cone", "type": "spot", "intensity": 3.0, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.4}},
    {"name": "sun", "type": "directional", "intensity": 2.0}
  ]}},
  "scenes": [{"nodes": [0, 1, 2]}],
  "nodes": [
    {"name": "a", "translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 0}}},
    {"name": "b", "translation": [0, 4, 0], "rotation": [-0.7071068, 0, 0, 0.7071068],
     "extensions": {"KHR_lights_punctual": {"light": 1}}},
    {"name": "c", "extensions": {"KHR_lights_punctual": {"light": %LIGHT%}}}
  ]
})";

tinygltf::Model parse(const std::string& text) {
    tinygltf::TinyGLTF parser;
    tinygltf::Model model;
    std::string error, warning;
    EXPECT_TRUE(parser.LoadASCIIFromString(&model, &error, &warning, text.c_str(), unsigned(text.size()), ""))
        << error;
    return model;
}

std::string with_light(int index) {
    std::string text = kLightsGltf;
    text.replace(text.find("%LIGHT%"), 7, std::to_string(index));
    return text;
}

TEST(PunctualLights, ParsedFromGltf) {
    const tinygltf::Model model = parse(with_light(2));
    // World transforms as the loader's node walk gives them: b turns -z to -y.
    const glm::dmat4 b = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 4, 0)), -kPi / 2, glm::dvec3(1, 0, 0));
    const std::vector<PunctualLight> lights = punctual_lights(
        model, {{0, glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3))}, {1, b}, {2, glm::dmat4(1.0)}}, "lights.gltf");
    ASSERT_EQ(lights.size(), 3u);
    EXPECT_EQ(lights[0].type, WF_PUNCTUAL_POINT);
    EXPECT_EQ(glm::vec3(lights[0].position[0], lights[0].position[1], lights[0].position[2]), glm::vec3(1, 2, 3));
    EXPECT_EQ(glm::vec3(lights[0].intensity[0], lights[0].intensity[1], lights[0].intensity[2]), glm::vec3(8, 4, 2));
    EXPECT_EQ(lights[1].type, WF_PUNCTUAL_SPOT);
    EXPECT_NEAR(lights[1].direction[1], -1.0f, 1e-6f);
    EXPECT_NEAR(lights[1].cos_inner, std::cos(0.2), 1e-6);
    EXPECT_NEAR(lights[1].cos_outer, std::cos(0.4), 1e-6);
    EXPECT_EQ(lights[2].type, WF_PUNCTUAL_DIRECTIONAL);
    EXPECT_EQ(lights[2].direction[2], -1.0f);
    EXPECT_EQ(lights[2].intensity[1], 2.0f);
    // The spot, seen straight below at distance 2: I / r^2.
    EXPECT_NEAR(wf_device::punctual_sample(lights[1], glm::vec3(0, 2, 0)).Li.x, 3.0f / 4.0f, 1e-5f);
}

TEST(PunctualLights, BadLightIndexNamesFileAndNode) {
    const tinygltf::Model model = parse(with_light(7));
    try {
        punctual_lights(model, {{2, glm::dmat4(1.0)}}, "lights.gltf");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "lights.gltf: node 2 'c': KHR_lights_punctual light 7 does not exist");
    }
}

const char* kPunctualKernel = R"(
__kernel void punctual_test(__global const PunctualLight* lights, __global const float* receivers,
                            __global float* out) {
    const uint i = get_global_id(0);
    const PunctualSample s = punctual_sample(lights[i % 3], vload3(i, receivers));
    __global float* o = out + 7 * i;
    o[0] = s.direction.x; o[1] = s.direction.y; o[2] = s.direction.z; o[3] = s.distance;
    o[4] = s.Li.x; o[5] = s.Li.y; o[6] = s.Li.z;
}
)";

// The device compiles the same header and agrees with the host.
TEST(PunctualLights, DeviceAgreesWithHost) {
    const OpenClDevice& device = test::cpu_device();
    const cl::Program program = test::build_test_program(expand_kernel_source("lights/punctual.h") + kPunctualKernel);
    std::vector<PunctualLight> lights = {light(WF_PUNCTUAL_POINT, glm::vec3(0, 2, 0), glm::vec3(0, -1, 0), 4.0f),
                                         light(WF_PUNCTUAL_SPOT, glm::vec3(1, 3, 0), glm::vec3(0, -1, 0), 2.0f),
                                         light(WF_PUNCTUAL_DIRECTIONAL, glm::vec3(0), glm::vec3(0, -0.6f, 0.8f), 1.0f)};
    lights[1].cos_inner = 0.95f;
    lights[1].cos_outer = 0.8f;
    const size_t n = 300;
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    std::vector<float> receivers(3 * n);
    for (size_t i = 0; i < n; ++i) receivers[3 * i] = u(rng), receivers[3 * i + 1] = 0.0f, receivers[3 * i + 2] = u(rng);
    cl::Buffer lb(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lights.size() * sizeof(PunctualLight), lights.data());
    cl::Buffer rb(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, receivers.size() * sizeof(float), receivers.data());
    cl::Buffer out(device.context, CL_MEM_WRITE_ONLY, 7 * n * sizeof(float));
    cl::Kernel kernel(program, "punctual_test");
    kernel.setArg(0, lb);
    kernel.setArg(1, rb);
    kernel.setArg(2, out);
    device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(n));
    std::vector<float> o(7 * n);
    device.queue.enqueueReadBuffer(out, CL_TRUE, 0, o.size() * sizeof(float), o.data());
    for (size_t i = 0; i < n; ++i) {
        const auto h = wf_device::punctual_sample(lights[i % 3], glm::vec3(receivers[3 * i], 0.0f, receivers[3 * i + 2]));
        const float* g = &o[7 * i];
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(g[k], h.direction[k], 1e-6f) << i;
            EXPECT_NEAR(g[4 + k], h.Li[k], 1e-5f * (1.0f + h.Li[k])) << i;
        }
        EXPECT_EQ(std::isinf(g[3]), std::isinf(h.distance)) << i;
        if (!std::isinf(h.distance)) EXPECT_NEAR(g[3], h.distance, 1e-5f) << i;
    }
}

} // namespace
} // namespace wf
