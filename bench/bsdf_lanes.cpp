// bsdf_lanes.cpp — wavefront_bsdf_lanes: what shading in SIMD lanes would buy
// on this OpenCL device (issue 16). Evaluates the same GGX metal for 4M random
// (wo, wi) pairs with the three kernels of bsdf_lanes.cl — the renderer's
// general BSDF, one BSDF kind without branches, and that kind in float8 lanes
// — compares their results with the general BSDF's (the restated kinds agree
// to the bit in f and to a few ulp in the pdf), and prints each one's rate.
// PoCL vectorises none of them across work-items (POCL_VECTORIZER_REMARKS=1
// says why); metal_lanes shows what explicit lanes would.
//
// Usage: build/bench/wavefront_bsdf_lanes [--device SPEC]

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "device/opencl_device.h"

namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Unit vectors with z > 0: the upper hemisphere, where a metal reflects.
std::vector<cl_float4> random_directions(size_t count, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> normal;
    std::vector<cl_float4> directions(count);
    for (cl_float4& d : directions) {
        const float x = normal(rng), y = normal(rng), z = std::fabs(normal(rng));
        const float length = std::sqrt(x * x + y * y + z * z);
        d = {{x / length, y / length, z / length, 0.0f}};
    }
    return directions;
}

// How many representable floats lie between a and b (both finite, same sign or zero).
long long ulps_apart(float a, float b) {
    int32_t ia, ib;
    std::memcpy(&ia, &a, sizeof ia);
    std::memcpy(&ib, &b, sizeof ib);
    return std::llabs(static_cast<long long>(ia) - static_cast<long long>(ib));
}

} // namespace

int main(int argc, char** argv) {
    const std::string spec = argc == 3 && std::strcmp(argv[1], "--device") == 0 ? argv[2] : "cpu";
    const wf::OpenClDevice device = wf::open_device(spec);
    cl::Program program(device.context, read_text(WF_SOURCE_DIR "/bench/bsdf_lanes.cl"));
    const std::string options = "-cl-std=CL1.2 -I" WF_SOURCE_DIR "/kernels -I" WF_SOURCE_DIR "/include";
    if (program.build({device.info.device}, options.c_str()) != CL_SUCCESS) {
        std::fprintf(stderr, "%s\n", program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device.info.device).c_str());
        return 1;
    }
    const size_t pairs = size_t(1) << 22, local = 64;
    const std::vector<cl_float4> wo = random_directions(pairs, 1), wi = random_directions(pairs, 2);
    cl::Buffer wo_buffer(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, pairs * sizeof(cl_float4),
                         const_cast<cl_float4*>(wo.data()));
    cl::Buffer wi_buffer(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, pairs * sizeof(cl_float4),
                         const_cast<cl_float4*>(wi.data()));
    cl::Buffer out_buffer(device.context, CL_MEM_WRITE_ONLY, pairs * sizeof(cl_float4));

    const cl_float3 base_color = {{0.95f, 0.64f, 0.54f}}; // a rough gold-coloured metal
    const float roughness = 0.5f;

    std::printf("%s: %zu evaluations of a GGX metal, local size %zu, best of 5\n", device.info.name.c_str(), pairs,
                local);
    std::vector<cl_float4> reference;
    double general_rate = 0.0;
    for (const char* name : {"general_eval", "metal_scalar", "metal_lanes"}) {
        const size_t per_item = std::strcmp(name, "metal_lanes") == 0 ? 8 : 1;
        cl::Kernel kernel(program, name);
        kernel.setArg(0, wo_buffer);
        kernel.setArg(1, wi_buffer);
        kernel.setArg(2, out_buffer);
        kernel.setArg(3, base_color);
        kernel.setArg(4, roughness);
        double best = 1e30;
        for (int round = 0; round < 6; ++round) { // the first compiles the kernel
            cl::Event done;
            device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(pairs / per_item), cl::NDRange(local),
                                              nullptr, &done);
            done.wait();
            const double seconds = (done.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                                    done.getProfilingInfo<CL_PROFILING_COMMAND_START>()) * 1e-9;
            if (round > 0) best = std::min(best, seconds);
        }
        std::vector<cl_float4> out(pairs);
        device.queue.enqueueReadBuffer(out_buffer, CL_TRUE, 0, pairs * sizeof(cl_float4), out.data());
        if (reference.empty()) reference = out;
        size_t differing = 0, nonzero = 0;
        long long max_ulps = 0;
        for (size_t i = 0; i < pairs; ++i) {
            differing += std::memcmp(&out[i], &reference[i], sizeof(cl_float4)) != 0;
            nonzero += out[i].s[3] > 0.0f;
            for (int c = 0; c < 4; ++c) max_ulps = std::max(max_ulps, ulps_apart(out[i].s[c], reference[i].s[c]));
        }
        const double rate = pairs / best * 1e-6;
        if (general_rate == 0.0) general_rate = rate;
        std::printf("  %-13s %7.1f M evaluations/s  %5.2fx general_eval  %zu nonzero, %zu differ (at most %lld ulp)\n",
                    name, rate, rate / general_rate, nonzero, differing, max_ulps);
    }
    return 0;
}
