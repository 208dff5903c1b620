// test_sobol.cpp — the Owen-scrambled Sobol sampler of kernels/common/sobol.h,
// compiled as host C++: its table against the Joe–Kuo recurrence, the
// unscrambled sequence against its definition, the stratification the
// scrambling must keep, the independence of keys, and the integration error
// against independent random numbers; then the point in lanes against the
// coordinate-by-coordinate definition, and the CPU device's 512-bit form of
// it against the host's, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <random>
#include <vector>

#include "common/sobol.h"
#include "device/kernel_sources.h"
#include "support/test_support.h"

namespace {

using wf_device::sobol_uniform4;

// Generator matrix columns of one dimension, from Joe and Kuo's recurrence for
// primitive polynomial degree s, coefficients a (bit s-1-i is a_i) and initial
// m_1 .. m_s: m_k = 2 a_1 m_{k-1} ^ 4 a_2 m_{k-2} ^ ... ^ 2^s m_{k-s} ^ m_{k-s}.
std::vector<uint32_t> joe_kuo_columns(unsigned s, uint32_t a, std::vector<uint32_t> m) {
    for (unsigned k = s; k < 32; ++k) {
        uint32_t next = m[k - s] ^ (m[k - s] << s);
        for (unsigned i = 1; i < s; ++i)
            if ((a >> (s - 1 - i)) & 1u) next ^= m[k - i] << i;
        m.push_back(next);
    }
    std::vector<uint32_t> columns(32);
    for (unsigned j = 0; j < 32; ++j) columns[j] = m[j] << (31 - j);
    return columns;
}

// All four dimensions; dimension 0 is van der Corput, column j = 2^(31-j).
std::vector<std::vector<uint32_t>> reference_matrices() {
    std::vector<uint32_t> van_der_corput(32);
    for (unsigned j = 0; j < 32; ++j) van_der_corput[j] = 1u << (31 - j);
    return {van_der_corput, joe_kuo_columns(1, 0, {1}), joe_kuo_columns(2, 1, {1, 3}),
            joe_kuo_columns(3, 1, {1, 3, 1})};
}

// Sobol's definition: the XOR of the columns of the index's set bits.
float reference_sobol(const std::vector<uint32_t>& columns, uint32_t index) {
    uint32_t bits = 0;
    for (unsigned j = 0; j < 32; ++j)
        if ((index >> j) & 1u) bits ^= columns[j];
    return float(bits >> 8) / 16777216.0f;
}

struct Key {
    uint32_t seed, pixel, bounce, group;
};

const Key kKeys[] = {{0, 0, 0, 0},      {0, 1, 0, 0},        {0, 0, 1, 0},         {0, 0, 0, 2},
                     {7, 123456, 3, 1}, {42, 0xffffffffu, 9, 2}, {0xdeadbeefu, 777, 0, 1}};

std::vector<glm::vec4> points(const Key& k, uint32_t first, uint32_t count) {
    std::vector<glm::vec4> p;
    for (uint32_t i = 0; i < count; ++i) p.push_back(sobol_uniform4(k.seed, k.pixel, first + i, k.bounce, k.group));
    return p;
}

// Every elementary interval of area 1/n (n = 2^m, all 2^i x 2^(m-i) shapes)
// holds exactly one of the n points in coordinates (a, b). The values are
// multiples of 2^-24, so scaling by a power of two and truncating is exact.
void expect_0m2_net(const std::vector<glm::vec4>& p, int a, int b) {
    const unsigned n = unsigned(p.size());
    for (unsigned nx = 1; nx <= n; nx *= 2) {
        const unsigned ny = n / nx;
        std::vector<int> count(n, 0);
        for (const glm::vec4& q : p) ++count[unsigned(q[a] * float(nx)) * ny + unsigned(q[b] * float(ny))];
        for (unsigned c = 0; c < n; ++c) ASSERT_EQ(count[c], 1) << nx << " x " << ny << " intervals, cell " << c;
    }
}

void expect_1d_stratified(const std::vector<glm::vec4>& p, int a) {
    const unsigned n = unsigned(p.size());
    std::vector<int> count(n, 0);
    for (const glm::vec4& q : p) ++count[unsigned(q[a] * float(n))];
    for (unsigned c = 0; c < n; ++c) ASSERT_EQ(count[c], 1) << "coordinate " << a << ", interval " << c;
}

TEST(Sobol, MatricesMatchJoeKuoRecurrence) {
    const auto reference = reference_matrices();
    for (unsigned d = 0; d < WF_SOBOL_DIMENSIONS; ++d)
        for (unsigned j = 0; j < 32; ++j)
            EXPECT_EQ(wf_device::sobol_matrices[4 * j + d], reference[d][j]) << "dimension " << d << ", bit " << j;
}

TEST(Sobol, UnscrambledSequenceIsSobols) {
    // The first points, worked out by hand from the columns 1/2, 1/4, 1/8 and
    // 1/2, 3/4, 5/8 of dimensions 0 and 1.
    const float dim0[] = {0.0f, 0.5f, 0.25f, 0.75f, 0.125f, 0.625f, 0.375f, 0.875f};
    const float dim1[] = {0.0f, 0.5f, 0.75f, 0.25f, 0.625f, 0.125f, 0.375f, 0.875f};
    for (uint32_t i = 0; i < 8; ++i) {
        EXPECT_EQ(wf_device::sobol_sample(i, 0), dim0[i]) << i;
        EXPECT_EQ(wf_device::sobol_sample(i, 1), dim1[i]) << i;
    }
    const auto reference = reference_matrices();
    std::mt19937 random(1);
    for (unsigned d = 0; d < WF_SOBOL_DIMENSIONS; ++d) {
        for (uint32_t i = 0; i < 4096; ++i) ASSERT_EQ(wf_device::sobol_sample(i, d), reference_sobol(reference[d], i));
        for (int t = 0; t < 4096; ++t) {
            const uint32_t i = uint32_t(random());
            ASSERT_EQ(wf_device::sobol_sample(i, d), reference_sobol(reference[d], i)) << i;
        }
        // The last index sets every bit; its point is still below 1.
        EXPECT_EQ(wf_device::sobol_sample(0xffffffffu, d), reference_sobol(reference[d], 0xffffffffu));
        EXPECT_LT(wf_device::sobol_sample(0xffffffffu, d), 1.0f);
    }
}

TEST(Sobol, ScrambledPrefixesAreNets) {
    for (const Key& k : kKeys) {
        // The first 256 points, a later aligned block of 256, and 1024 points.
        for (uint32_t first : {0u, 256u * 37u}) {
            const auto p = points(k, first, 256);
            expect_0m2_net(p, 0, 1);
            expect_1d_stratified(p, 2);
            expect_1d_stratified(p, 3);
        }
        const auto p = points(k, 0, 1024);
        expect_0m2_net(p, 0, 1);
        expect_1d_stratified(p, 2);
        expect_1d_stratified(p, 3);
    }
}

TEST(Sobol, KeysScrambleIndependentlyAndValuesStayInUnitInterval) {
    for (size_t a = 0; a < std::size(kKeys); ++a)
        for (size_t b = a + 1; b < std::size(kKeys); ++b)
            for (uint32_t i = 0; i < 16; ++i) {
                const glm::vec4 pa = points(kKeys[a], i, 1)[0], pb = points(kKeys[b], i, 1)[0];
                for (int c = 0; c < 4; ++c)
                    EXPECT_NE(pa[c], pb[c]) << "keys " << a << " and " << b << ", sample " << i << ", coordinate " << c;
            }
    std::mt19937 random(2);
    for (int t = 0; t < 100000; ++t) {
        const uint32_t sample = t < 1000 ? 0xffffffffu - uint32_t(t) : uint32_t(random());
        const glm::vec4 p = sobol_uniform4(random(), random(), sample, random() % 64, random() % 3);
        for (int c = 0; c < 4; ++c) {
            ASSERT_GE(p[c], 0.0f);
            ASSERT_LT(p[c], 1.0f);
        }
    }
}

// The hash stands in for Owen's independent random flips: for two numbers that
// first differ at bit j (from the top), the flips of a lower bit k must agree
// for half the seeds. A weak hash (such as the original four-multiply
// Laine–Karras form) is off by more than 0.1 for some (j, k).
TEST(Sobol, OwenScrambleFlipsLookIndependent) {
    std::mt19937 random(3);
    const int trials = 4000;
    double worst = 0.0;
    for (int j = 0; j < 31; ++j)
        for (int k = j + 1; k < 32; ++k) {
            int agree = 0;
            for (int t = 0; t < trials; ++t) {
                const uint32_t seed = random(), x = random();
                // y shares x's top j bits, differs in the next, and is random below.
                const uint32_t prefix = j == 0 ? 0u : 0xffffffffu << (32 - j);
                const uint32_t y = (x & prefix) | (~x & (0x80000000u >> j)) | (random() & ((0x80000000u >> j) - 1));
                const uint32_t flips_x = wf_device::sobol_owen_scramble(x, seed) ^ x;
                const uint32_t flips_y = wf_device::sobol_owen_scramble(y, seed) ^ y;
                ASSERT_EQ((flips_x ^ flips_y) & prefix, 0u) << "bits above the first difference must flip alike";
                agree += ((flips_x ^ flips_y) >> (31 - k) & 1u) == 0;
            }
            worst = std::max(worst, std::abs(agree / double(trials) - 0.5));
        }
    // 4000 trials: standard deviation 0.008; the largest of 496 pairs stays
    // below 0.035 for independent flips.
    EXPECT_LT(worst, 0.045);
}

TEST(Sobol, IntegratesFarBetterThanIndependentSamples) {
    const int pixels = 64, n = 1024;
    std::mt19937 random(4);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    double sobol_squared_error = 0.0, independent_squared_error = 0.0;
    for (int pixel = 0; pixel < pixels; ++pixel) {
        double sobol_sum = 0.0, independent_sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const glm::vec4 p = sobol_uniform4(5, uint32_t(pixel), uint32_t(i), 1, 2);
            sobol_sum += double(p.x) * p.y;
            independent_sum += double(uniform(random)) * uniform(random);
        }
        const double sobol_error = sobol_sum / n - 0.25, independent_error = independent_sum / n - 0.25;
        EXPECT_LT(std::abs(sobol_error), 1e-4) << "pixel " << pixel;
        sobol_squared_error += sobol_error * sobol_error;
        independent_squared_error += independent_error * independent_error;
    }
    EXPECT_LT(sobol_squared_error, independent_squared_error / 10.0);
}

// sobol_uniform4 takes the four coordinates in lanes; each must be what its
// definition gives alone: the point's bits for the scrambled index, each
// Owen-scrambled with its coordinate's seed.
TEST(Sobol, LanesGiveEachCoordinatesDefinition) {
    std::mt19937 random(6);
    for (int t = 0; t < 20000; ++t) {
        const uint32_t seed = random(), pixel = random(), sample = random(), bounce = random() % 64, group = random() % 3;
        const glm::vec4 p = sobol_uniform4(seed, pixel, sample, bounce, group);
        const uint32_t key = wf_device::sobol_hash(
            wf_device::sobol_hash(wf_device::sobol_hash(wf_device::sobol_hash(seed) ^ pixel) ^ bounce) ^ group);
        const uint32_t index = wf_device::sobol_owen_scramble(sample, key);
        for (uint32_t d = 0; d < WF_SOBOL_DIMENSIONS; ++d) {
            const uint32_t coordinate_seed = wf_device::sobol_hash(key ^ (0x9e3779b9u * (d + 1u)));
            const float expected = wf_device::sobol_bits_to_float(
                wf_device::sobol_owen_scramble(wf_device::sobol_bits(index, d), coordinate_seed));
            ASSERT_EQ(p[int(d)], expected) << "coordinate " << d;
        }
    }
}

const char* kSobolKernel = R"(
__kernel void sobol_points(__global const uint* keys, __global float4* out, uint n) {
    const uint i = get_global_id(0);
    if (i >= n) return;
    out[i] = sobol_uniform4(keys[5 * i], keys[5 * i + 1], keys[5 * i + 2], keys[5 * i + 3], keys[5 * i + 4]);
}
)";

// The device computes the host's bits: on a CPU device through sixteen
// columns at a time (sobol_point_bits), on the host a bit at a time.
TEST(SobolDevice, HostAndPoclGiveTheSameBits) {
    const size_t n = 4096;
    std::mt19937 random(7);
    std::vector<cl_uint> keys(5 * n);
    for (size_t i = 0; i < n; ++i) {
        keys[5 * i] = random();
        keys[5 * i + 1] = random();
        keys[5 * i + 2] = i < 64 ? cl_uint(i) : (i < 128 ? 0xffffffffu - cl_uint(i) : cl_uint(random()));
        keys[5 * i + 3] = random() % 64;
        keys[5 * i + 4] = random() % 3;
    }
    const wf::OpenClDevice& device = wf::test::cpu_device();
    const cl::Program program = wf::test::build_test_program(wf::expand_kernel_source("common/sobol.h") + kSobolKernel);
    cl::Buffer key_buffer(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, keys.size() * sizeof(cl_uint),
                          keys.data());
    cl::Buffer out(device.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    cl::Kernel kernel(program, "sobol_points");
    kernel.setArg(0, key_buffer);
    kernel.setArg(1, out);
    kernel.setArg(2, cl_uint(n));
    device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(n), cl::NDRange(64));
    std::vector<cl_float4> on_device(n);
    device.queue.enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(cl_float4), on_device.data());
    for (size_t i = 0; i < n; ++i) {
        const glm::vec4 host = sobol_uniform4(keys[5 * i], keys[5 * i + 1], keys[5 * i + 2], keys[5 * i + 3], keys[5 * i + 4]);
        for (int c = 0; c < 4; ++c) ASSERT_EQ(on_device[i].s[c], host[c]) << "point " << i << ", coordinate " << c;
    }
}

} // namespace
