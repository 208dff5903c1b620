// bsdf_lanes.cpp — wavefront_bsdf_lanes: what the BSDF kinds and their lanes
// buy on this OpenCL device, measured on the renderer's own code
// (kernels/bsdf/kind_probe.cl): the whole BSDF core of one shading point (the
// BSDF at a light sample's direction, and a sampled continuation) for 4M
// random queries on opaque materials (the Cornell box's white and a rough
// gold; with --coated, ToyCar's: a clear coat over a dielectric, and a red
// sheen over a rough dielectric; with --glass, the Cornell glass sphere's
// smooth solid and a rough one, seen from outside and inside), four ways: the
// general BSDF, and the layered kind at widths 1, 8 and 16, each built with
// the lobes such a scene's program has. Prints each one's rate, and checks
// the lanes give width 1's bits.
//
// Usage: build/bench/wavefront_bsdf_lanes [--coated | --glass] [--device SPEC]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "device/kernel_sources.h"
#include "device/opencl_device.h"
#include "wavefront/techniques.h"

namespace {

// kind_probe.cl's probe_query fields (the layered kind's 18 parameters, its
// coat's, sheen's and transmission's left 0 here, then wo, wi, u), and answers.
constexpr int kParams = 18, kFields = kParams + 9, kAnswer = 12;

enum class Materials { Opaque, Coated, Glass };

// The Cornell box's white (a rough dielectric over its base) and a rough gold
// metal, alternately, at random wo (above the surface), wi and u; coated:
// ToyCar's coated body and sheened fabric instead; glass: a clear smooth
// solid and one of roughness 0.3, wo on either side.
std::vector<float> random_queries(size_t n, Materials materials) {
    const bool coated = materials == Materials::Coated, glass = materials == Materials::Glass;
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::normal_distribution<float> normal;
    std::vector<float> in(kFields * n);
    auto set = [&](int field, size_t i, float v) { in[field * n + i] = v; };
    for (size_t i = 0; i < n; ++i) {
        const bool gold = i % 2;
        const float base[3] = {gold ? 0.95f : 0.725f, gold ? 0.64f : 0.71f, gold ? 0.54f : 0.68f};
        const float params[7] = {gold ? 1.0f : 0.0f, gold ? 0.5f : 1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.5f};
        for (int k = 0; k < 3; ++k) set(k, i, base[k]);
        for (int k = 0; k < 7; ++k) set(3 + k, i, params[k]); // metallic, roughness, specular, its colour, ior
        if (coated) {
            // The body: a clear coat of roughness 0.05 over a glossy dielectric; the fabric:
            // a red sheen of roughness 0.5 over a rough dark dielectric.
            const float body[3] = {0.6f, 0.1f, 0.1f}, fabric[3] = {0.15f, 0.15f, 0.15f};
            for (int k = 0; k < 3; ++k) set(k, i, gold ? fabric[k] : body[k]);
            set(3, i, 0.0f), set(4, i, gold ? 1.0f : 0.3f);
            set(10, i, gold ? 0.0f : 1.0f), set(11, i, 0.05f);                       // clear coat, roughness
            set(12, i, gold ? 1.0f : 0.0f), set(13, i, 0.0f), set(14, i, 0.0f), set(15, i, 0.5f); // sheen
        }
        if (glass) { // white, clear, ior 1.5; smooth, or rough (the second of each pair)
            for (int k = 0; k < 3; ++k) set(k, i, 1.0f);
            set(3, i, 0.0f), set(4, i, gold ? 0.3f : 0.0f), set(16, i, 1.0f); // metallic, roughness, transmission
        }
        for (int d = 0; d < 2; ++d) {
            float v[3] = {normal(rng), normal(rng), normal(rng)};
            const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            if (d == 0 && !(glass && u01(rng) < 0.5f)) v[2] = std::fabs(v[2]); // a solid is seen from inside too
            for (int k = 0; k < 3; ++k) set(kParams + 3 * d + k, i, v[k] / length);
        }
        for (int k = 0; k < 3; ++k) set(kParams + 6 + k, i, u01(rng));
    }
    return in;
}

} // namespace

int main(int argc, char** argv) {
    Materials materials = Materials::Opaque;
    std::string spec = "cpu";
    for (int a = 1; a < argc; ++a) {
        if (std::strcmp(argv[a], "--coated") == 0) {
            materials = Materials::Coated;
        } else if (std::strcmp(argv[a], "--glass") == 0) {
            materials = Materials::Glass;
        } else if (std::strcmp(argv[a], "--device") == 0 && a + 1 < argc) {
            spec = argv[++a];
        } else {
            std::fprintf(stderr, "wavefront_bsdf_lanes: unknown argument %s; usage: [--coated | --glass] [--device SPEC]\n",
                         argv[a]);
            return 2;
        }
    }
    const wf::OpenClDevice device = wf::open_device(spec);
    cl::Program program(device.context, wf::expand_kernel_source("bsdf/kind_probe.cl"));
    // The kind as a program of the scene compiles it: without coats, sheens
    // or transmission for the Cornell box's materials, with the coat and
    // sheen for ToyCar's, with the transmission alone for the glass sphere's.
    const char* lobes[] = {" -DWF_HAS_TRANSMISSION=0 -DWF_HAS_CLEARCOAT=0 -DWF_HAS_SHEEN=0",
                           " -DWF_HAS_TRANSMISSION=0", " -DWF_HAS_CLEARCOAT=0 -DWF_HAS_SHEEN=0"};
    const std::string options = std::string("-cl-std=CL1.2 -DWF_LANE_WIDTH=8") + lobes[int(materials)];
    if (program.build({device.info.device}, options.c_str()) != CL_SUCCESS) {
        std::fprintf(stderr, "%s\n", program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device.info.device).c_str());
        return 1;
    }
    const size_t n = size_t(1) << 22, local = 64;
    const std::vector<float> in = random_queries(n, materials);
    cl::Buffer input(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, in.size() * sizeof(float),
                     const_cast<float*>(in.data()));
    cl::Buffer output(device.context, CL_MEM_WRITE_ONLY, kAnswer * n * sizeof(float));

    const char* described[] = {"opaque", "coated and sheened", "glass"};
    std::printf("%s: the BSDF core (eval at the light sample + sample) of %zu %s queries, local size %zu, best of 5\n",
                device.info.name.c_str(), n, described[int(materials)], local);
    std::vector<float> width_one;
    double general_rate = 0.0;
    for (const auto& [name, width] : std::vector<std::pair<const char*, int>>{
             {"general_probe", 1}, {"layered_probe_x1", 1}, {"layered_probe_x8", 8}, {"layered_probe_x16", 16}}) {
        cl::Kernel kernel(program, name);
        kernel.setArg(0, input);
        kernel.setArg(1, cl_uint(n));
        kernel.setArg(2, cl_uint(WF_HEMISPHERE_COSINE));
        kernel.setArg(3, output);
        double best = 1e30;
        for (int round = 0; round < 6; ++round) { // the first compiles the kernel
            cl::Event done;
            device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(n / width), cl::NDRange(local),
                                              nullptr, &done);
            done.wait();
            const double seconds = (done.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                                    done.getProfilingInfo<CL_PROFILING_COMMAND_START>()) * 1e-9;
            if (round > 0) best = std::min(best, seconds);
        }
        std::vector<float> out(kAnswer * n);
        device.queue.enqueueReadBuffer(output, CL_TRUE, 0, out.size() * sizeof(float), out.data());
        std::string agreement;
        if (width == 1 && std::strcmp(name, "layered_probe_x1") == 0) width_one = out;
        if (width > 1) { // lanes write field-major
            size_t differing = 0;
            for (size_t i = 0; i < n; ++i)
                for (int k = 0; k < kAnswer; ++k)
                    differing += std::memcmp(&out[k * n + i], &width_one[kAnswer * i + k], sizeof(float)) != 0;
            agreement = "  " + std::to_string(differing) + " values differ from width 1's";
        }
        const double rate = n / best * 1e-6;
        if (general_rate == 0.0) general_rate = rate;
        std::printf("  %-17s %7.1f M queries/s  %5.2fx the general BSDF%s\n", name, rate, rate / general_rate,
                    agreement.c_str());
    }
    return 0;
}
