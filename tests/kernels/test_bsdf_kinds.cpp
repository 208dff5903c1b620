// test_bsdf_kinds.cpp — the BSDF kinds (kernels/bsdf/kinds.h) against the
// general BSDF (bsdf/bsdf.h), their oracle, on the device:
//  1. for random materials (metal and dielectric, rough and smooth,
//     coloured specular, under no clear coat or a rough or smooth one, with
//     and without a sheen, opaque or transmitting as a thin wall or a solid
//     seen from outside or inside, either hemisphere sampler) and random wo,
//     wi, u, the
//     layered kind at width 1 gives the general BSDF's f and pdf at wi and its
//     sample (direction, f, pdf, Dirac or not) to within float rounding;
//  2. at widths 8 and 16 it gives width 1's answers to the bit, so the group
//     schedule's lanes and the megakernel make the same image bytes.
// The general BSDF's own properties (sampling matches pdf, reciprocity,
// energy) are test_bsdf.cpp's; (1) carries them over to the kind.
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "device/kernel_sources.h"
#include "support/test_support.h"
#include "wavefront/techniques.h"

namespace wf {
namespace {

// The inputs, a structure of arrays: each field's n values in turn, the
// kind's parameters in the order of its list (kernels/bsdf/kinds/layered.inc),
// then wo, wi and u (kernels/bsdf/kind_probe.cl's probe_query).
enum Field { BASE_R, BASE_G, BASE_B, METALLIC, ROUGHNESS, SPECULAR, SPEC_R, SPEC_G, SPEC_B, IOR,
             CLEARCOAT, CLEARCOAT_ROUGHNESS, SHEEN_R, SHEEN_G, SHEEN_B, SHEEN_ROUGHNESS, TRANSMISSION, THIN_WALLED,
             WO_X, WO_Y, WO_Z, WI_X, WI_Y, WI_Z, U_X, U_Y, U_Z, FIELD_COUNT };
// The answers per item: f at wi (3), its pdf, the sample's wi (3), f (3), pdf, delta.
constexpr int kAnswer = 12;



struct Items {
    std::vector<float> in; // FIELD_COUNT x n
    size_t n;
};

// Materials of every sort, at random directions: wo above the surface (the
// kind's domain; shade flips the frame so) but for a solid that transmits,
// which is seen from inside too (wo.z < 0); wi on either side; one item in
// eleven at an extreme (normal incidence, grazing, the mirror direction, u at 0
// or just below 1), where a lobe's formulas meet 0/0 or overflow first.
Items random_items(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    Items items{std::vector<float>(FIELD_COUNT * n), n};
    auto set = [&](int field, size_t i, float v) { items.in[field * n + i] = v; };
    for (size_t i = 0; i < n; ++i) {
        const int sort = int(i % 6);
        set(BASE_R, i, u01(rng)), set(BASE_G, i, u01(rng)), set(BASE_B, i, u01(rng));
        set(METALLIC, i, sort == 0 ? 0.0f : sort == 1 ? 1.0f : u01(rng));
        set(ROUGHNESS, i, sort == 2 ? 0.01f : sort == 3 ? 1.0f : u01(rng)); // 0.01: a Dirac interface
        set(SPECULAR, i, sort == 4 ? 0.0f : sort == 5 ? u01(rng) : 1.0f);
        set(SPEC_R, i, sort == 5 ? 2.0f * u01(rng) : 1.0f), set(SPEC_G, i, 1.0f), set(SPEC_B, i, 1.0f);
        set(IOR, i, sort == 5 ? 1.0f + 2.0f * u01(rng) : 1.5f);
        const int coat = int(i / 6 % 4); // none; rough; a Dirac mirror at full weight; roughness 1
        set(CLEARCOAT, i, coat == 0 ? 0.0f : coat == 2 ? 1.0f : u01(rng));
        set(CLEARCOAT_ROUGHNESS, i, coat == 2 ? 0.01f : coat == 3 ? 1.0f : u01(rng));
        const int sheen = int(i / 24 % 3); // none; red (one channel, as ToyCar's fabric); any colour
        set(SHEEN_R, i, sheen == 0 ? 0.0f : u01(rng));
        set(SHEEN_G, i, sheen == 2 ? u01(rng) : 0.0f), set(SHEEN_B, i, sheen == 2 ? u01(rng) : 0.0f);
        set(SHEEN_ROUGHNESS, i, sheen == 2 && u01(rng) < 0.3f ? 0.0f : u01(rng)); // 0: below sheen.h's clamp
        const int glass = int(i / 72 % 3); // opaque; a thin wall; a solid
        set(TRANSMISSION, i, glass == 0 ? 0.0f : u01(rng) < 0.5f ? 1.0f : u01(rng));
        set(THIN_WALLED, i, glass == 1 ? 1.0f : 0.0f);
        if (glass != 0) // any ior, 1 among them (a Dirac interface whatever the roughness)
            set(IOR, i, u01(rng) < 0.1f ? 1.0f : 1.0f + 1.5f * u01(rng));
        for (int d = 0; d < 2; ++d) {
            float v[3] = {normal(rng), normal(rng), normal(rng)};
            const float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            if (d == 0) v[2] = std::fabs(v[2]);
            for (int k = 0; k < 3; ++k) set((d == 0 ? WO_X : WI_X) + k, i, v[k] / len);
        }
        set(U_X, i, u01(rng)), set(U_Y, i, u01(rng)), set(U_Z, i, u01(rng));
        if (i % 11 == 0) { // the extremes: normal incidence, grazing wo or wi, the mirror direction, u's ends
            const float grazing = 1e-6f, last = 0x1.fffffep-1f;
            switch (i / 11 % 6) {
            case 0: set(WO_X, i, 0.0f), set(WO_Y, i, 0.0f), set(WO_Z, i, 1.0f); break;
            case 1: set(WO_X, i, 1.0f), set(WO_Y, i, 0.0f), set(WO_Z, i, grazing); break;
            case 2: set(WI_X, i, 0.6f), set(WI_Y, i, 0.8f), set(WI_Z, i, i % 2 ? grazing : -grazing); break;
            case 3:
                set(WI_X, i, -items.in[WO_X * n + i]), set(WI_Y, i, -items.in[WO_Y * n + i]);
                set(WI_Z, i, items.in[WO_Z * n + i]);
                break;
            case 4: set(U_X, i, 0.0f), set(U_Y, i, 0.0f), set(U_Z, i, 0.0f); break;
            default: set(U_X, i, last), set(U_Y, i, last), set(U_Z, i, last); break;
            }
        }
        if (glass == 2 && u01(rng) < 0.5f) set(WO_Z, i, -items.in[WO_Z * n + i]); // from inside the solid
    }
    return items;
}

class BsdfKinds : public ::testing::TestWithParam<uint32_t> {}; // the hemisphere sampler

// Runs one probe kernel over every item, `width` items a work-item; the
// answers item-major.
std::vector<float> run_probe(const cl::Program& program, const char* name, const Items& items, uint32_t hemisphere,
                             int width) {
    const OpenClDevice& device = test::cpu_device();
    cl::Buffer input(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, items.in.size() * sizeof(float),
                     const_cast<float*>(items.in.data()));
    cl::Buffer output(device.context, CL_MEM_WRITE_ONLY, kAnswer * items.n * sizeof(float));
    cl::Kernel kernel(program, name);
    kernel.setArg(0, input);
    kernel.setArg(1, cl_uint(items.n));
    kernel.setArg(2, cl_uint(hemisphere));
    kernel.setArg(3, output);
    device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(items.n / width), cl::NullRange);
    std::vector<float> out(kAnswer * items.n);
    device.queue.enqueueReadBuffer(output, CL_TRUE, 0, out.size() * sizeof(float), out.data());
    if (width == 1) return out;
    std::vector<float> item_major(out.size());
    for (size_t i = 0; i < items.n; ++i)
        for (int k = 0; k < kAnswer; ++k) item_major[kAnswer * i + k] = out[k * items.n + i];
    return item_major;
}

cl::Program probe_program() {
    return test::build_test_program(expand_kernel_source("bsdf/kind_probe.cl"), "-DWF_LANE_WIDTH=8");
}

TEST_P(BsdfKinds, LayeredMatchesTheGeneralBsdf) {
    const Items items = random_items(4096, 11 + GetParam());
    const cl::Program program = probe_program();
    const std::vector<float> general = run_probe(program, "general_probe", items, GetParam(), 1);
    const std::vector<float> layered = run_probe(program, "layered_probe_x1", items, GetParam(), 1);
    // Restated arithmetic rounds differently: a relative 1e-4, except where a
    // value is a difference of nearly equal terms (an absolute 1e-5 of 1).
    auto close = [](float a, float b) { return std::fabs(a - b) <= 1e-4f * std::max(std::fabs(a), std::fabs(b)) + 1e-5f; };
    int differing = 0, samples = 0, deltas = 0;
    for (size_t i = 0; i < items.n; ++i) {
        const float* g = &general[kAnswer * i];
        const float* o = &layered[kAnswer * i];
        samples += g[10] > 0.0f;
        deltas += g[11] != 0.0f;
        bool same = true;
        for (int k = 0; k < kAnswer; ++k)
            // A sample that failed (pdf 0) carries no direction or value to compare.
            if (!(k >= 4 && k < 10 && g[10] == 0.0f && o[10] == 0.0f)) same = same && close(g[k], o[k]);
        if (!same && ++differing <= 5) {
            std::string row;
            for (int k = 0; k < kAnswer; ++k) row += " " + std::to_string(g[k]) + "/" + std::to_string(o[k]);
            ADD_FAILURE() << "item " << i << " (general/layered):" << row;
        }
    }
    test::report_measured("layered kind vs general BSDF: " + std::to_string(items.n) + " queries (" +
                          std::to_string(samples) + " samples, " + std::to_string(deltas) + " Dirac), " +
                          std::to_string(differing) + " differ");
    EXPECT_EQ(differing, 0);
    EXPECT_GT(samples, int(items.n / 2));
    EXPECT_GT(deltas, 0);
}

TEST_P(BsdfKinds, LayeredLanesGiveWidthOnesBits) {
    const Items items = random_items(4096, 23 + GetParam());
    const cl::Program program = probe_program();
    const std::vector<float> one = run_probe(program, "layered_probe_x1", items, GetParam(), 1);
    for (int width : {8, 16}) {
        const std::string name = "layered_probe_x" + std::to_string(width);
        const std::vector<float> lanes = run_probe(program, name.c_str(), items, GetParam(), width);
        int differing = 0;
        for (size_t i = 0; i < items.n; ++i)
            if (std::memcmp(&one[kAnswer * i], &lanes[kAnswer * i], kAnswer * sizeof(float)) != 0 && ++differing <= 3)
                ADD_FAILURE() << "width " << width << ", item " << i << ": not width 1's bits";
        EXPECT_EQ(differing, 0) << "width " << width;
    }
}

INSTANTIATE_TEST_SUITE_P(Hemisphere, BsdfKinds, ::testing::Values(uint32_t(WF_HEMISPHERE_COSINE), uint32_t(WF_HEMISPHERE_UNIFORM)));

} // namespace
} // namespace wf
