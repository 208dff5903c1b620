// test_texture.cpp — texture lookup: kernels/materials/texture.h compiled as
// host C++ against hand-computed values (texel centres, edges and corners
// under each wrap mode, KHR_texture_transform, sRGB decoded before filtering)
// and against the same header compiled by PoCL. The glTF side is
// tests/gltf/test_gltf_textures.cpp's.
#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "device/device_scene.h"
#include "device/kernel_sources.h"
#include "materials/texture.h"
#include "support/test_support.h"

namespace wf {
namespace {

using wf_device::texture_sample;
using wf_device::srgb_to_linear_table;

// A texture set built in code: each texture's texels given as bytes of R
// (G = B = R, A = 255) unless given in full.
struct TestTextures {
    std::vector<TextureInfo> infos;
    std::vector<uint32_t> texels;

    int32_t add(uint32_t width, uint32_t height, std::vector<uint32_t> rgba, uint32_t wrap_s, uint32_t wrap_t,
                uint32_t flags = 0) {
        TextureInfo info{};
        info.offset = uint32_t(texels.size());
        info.width = width;
        info.height = height;
        info.flags = flags;
        info.wrap_s = wrap_s;
        info.wrap_t = wrap_t;
        info.channels = 4;
        info.stride = 1;
        texels.insert(texels.end(), rgba.begin(), rgba.end());
        infos.push_back(info);
        return int32_t(infos.size() - 1);
    }
    int32_t add_grey(uint32_t width, uint32_t height, const std::vector<uint32_t>& r, uint32_t wrap_s,
                     uint32_t wrap_t, uint32_t flags = 0) {
        std::vector<uint32_t> rgba;
        for (uint32_t v : r) rgba.push_back(pack_rgba8(v, v, v, 255));
        return add(width, height, rgba, wrap_s, wrap_t, flags);
    }
    glm::vec4 sample(const TextureRef& ref, float u, float v) const {
        return texture_sample(infos.data(), texels.data(), &ref, glm::vec2(u, v));
    }
};

TextureRef ref_to(int32_t texture) {
    TextureRef ref = no_texture();
    ref.texture = texture;
    return ref;
}

// The 2×2 texture of R bytes t00 = 0, t10 = 51 (top row), t01 = 102, t11 = 255.
constexpr float kT00 = 0, kT10 = 51, kT01 = 102, kT11 = 255;

struct Expected {
    float u, v, bytes; // R at (u, v), in bytes (0..255)
};

void expect_samples(uint32_t wrap, const std::vector<Expected>& cases) {
    TestTextures t;
    const TextureRef ref = ref_to(t.add_grey(2, 2, {0, 51, 102, 255}, wrap, wrap));
    for (const Expected& e : cases)
        EXPECT_NEAR(t.sample(ref, e.u, e.v).x * 255.0f, e.bytes, 1e-3f)
            << "wrap " << wrap << " at (" << e.u << ", " << e.v << ")";
}

// Cases every wrap mode shares: texel centres and the middle.
const std::vector<Expected> kInterior = {{0.25f, 0.25f, kT00},
                                         {0.75f, 0.25f, kT10},
                                         {0.25f, 0.75f, kT01},
                                         {0.75f, 0.75f, kT11},
                                         {0.5f, 0.5f, (kT00 + kT10 + kT01 + kT11) / 4},
                                         {0.5f, 0.25f, (kT00 + kT10) / 2},
                                         {0.375f, 0.25f, 0.75f * kT00 + 0.25f * kT10}};

std::vector<Expected> with_interior(std::vector<Expected> cases) {
    cases.insert(cases.end(), kInterior.begin(), kInterior.end());
    return cases;
}

TEST(TextureBilinear, RepeatAtCentresEdgesAndCorners) {
    expect_samples(WF_WRAP_REPEAT, with_interior({
        {0.0f, 0.25f, (kT10 + kT00) / 2},                 // left edge: halfway to the wrapped right column
        {1.0f, 0.25f, (kT10 + kT00) / 2},                 // right edge: the same place
        {0.0f, 0.0f, (kT00 + kT10 + kT01 + kT11) / 4},    // corner: all four
        {-0.25f, 0.25f, kT10},                            // one period left
        {1.25f, 0.25f, kT00},
        {3.75f, -2.25f, kT11},
    }));
}

TEST(TextureBilinear, ClampToEdgeAtCentresEdgesAndCorners) {
    expect_samples(WF_WRAP_CLAMP_TO_EDGE, with_interior({
        {0.0f, 0.25f, kT00},
        {1.0f, 0.25f, kT10},
        {0.0f, 0.0f, kT00},
        {1.0f, 1.0f, kT11},
        {-0.25f, 0.25f, kT00},
        {1.25f, 0.75f, kT11},
        {-5.0f, 7.0f, kT01},
    }));
}

TEST(TextureBilinear, MirroredRepeatAtCentresEdgesAndCorners) {
    expect_samples(WF_WRAP_MIRRORED_REPEAT, with_interior({
        {0.0f, 0.25f, kT00},    // the mirror image of texel 0 is texel 0
        {1.0f, 0.25f, kT10},
        {0.0f, 0.0f, kT00},
        {-0.25f, 0.25f, kT00},  // mirrors to 0.25
        {1.25f, 0.25f, kT10},   // mirrors to 0.75
        {-1.25f, 0.25f, kT10},  // mirrors to 1.25, then to 0.75
        {2.25f, 0.75f, kT01},   // a whole period of 2 on
        {1.75f, 0.25f, kT00},
    }));
}

// An independent bilinear reference in double: texel centres at i + 0.5,
// wrap by integer arithmetic on the texel index.
double reference_bilinear(const std::vector<uint32_t>& bytes, int w, int h, uint32_t wrap, double u, double v) {
    const auto wrap_index = [wrap](long i, long n) -> long {
        if (wrap == WF_WRAP_CLAMP_TO_EDGE) return std::clamp(i, 0L, n - 1);
        if (wrap == WF_WRAP_MIRRORED_REPEAT) {
            long m = ((i % (2 * n)) + 2 * n) % (2 * n);
            return m < n ? m : 2 * n - 1 - m;
        }
        return ((i % n) + n) % n;
    };
    const double x = u * w - 0.5, y = v * h - 0.5;
    const long x0 = long(std::floor(x)), y0 = long(std::floor(y));
    const double tx = x - x0, ty = y - y0;
    const auto at = [&](long i, long j) { return double(bytes[size_t(wrap_index(j, h) * w + wrap_index(i, w))]); };
    return (1 - ty) * ((1 - tx) * at(x0, y0) + tx * at(x0 + 1, y0)) + ty * ((1 - tx) * at(x0, y0 + 1) + tx * at(x0 + 1, y0 + 1));
}

TEST(TextureBilinear, FourByFourMatchesReferenceEverywhere) {
    std::vector<uint32_t> bytes(16);
    for (uint32_t i = 0; i < 16; ++i) bytes[i] = (i * 37 + 11) % 256;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f);
    for (uint32_t wrap : {WF_WRAP_REPEAT, WF_WRAP_CLAMP_TO_EDGE, WF_WRAP_MIRRORED_REPEAT}) {
        TestTextures t;
        const TextureRef ref = ref_to(t.add_grey(4, 4, bytes, wrap, wrap));
        double worst = 0;
        for (int k = 0; k < 2000; ++k) {
            const float u = coordinate(rng), v = coordinate(rng);
            worst = std::max(worst, std::abs(t.sample(ref, u, v).x * 255.0 - reference_bilinear(bytes, 4, 4, wrap, u, v)));
        }
        EXPECT_LT(worst, 2e-3) << "wrap " << wrap;
    }
}

TEST(TextureBilinear, NearestFilterPicksTheTexelUnderUv) {
    TestTextures t;
    const TextureRef ref = ref_to(t.add_grey(2, 2, {0, 51, 102, 255}, WF_WRAP_REPEAT, WF_WRAP_REPEAT, WF_TEXTURE_NEAREST));
    EXPECT_FLOAT_EQ(t.sample(ref, 0.49f, 0.1f).x * 255.0f, kT00);
    EXPECT_FLOAT_EQ(t.sample(ref, 0.51f, 0.1f).x * 255.0f, kT10);
    EXPECT_FLOAT_EQ(t.sample(ref, 0.9f, 0.9f).x * 255.0f, kT11);
    EXPECT_FLOAT_EQ(t.sample(ref, -0.1f, 0.1f).x * 255.0f, kT10);
}

TEST(TextureBilinear, NoTextureReadsAsOne) {
    TestTextures t;
    t.add_grey(1, 1, {0}, WF_WRAP_REPEAT, WF_WRAP_REPEAT);
    EXPECT_EQ(t.sample(no_texture(), 0.3f, 0.3f), glm::vec4(1.0f));
}

TEST(TextureBilinear, NonFiniteAndHugeUvStayFiniteAndInRange) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (uint32_t wrap : {WF_WRAP_REPEAT, WF_WRAP_CLAMP_TO_EDGE, WF_WRAP_MIRRORED_REPEAT}) {
        TestTextures t;
        const TextureRef ref = ref_to(t.add_grey(2, 2, {0, 51, 102, 255}, wrap, wrap));
        const glm::vec4 at_zero = t.sample(ref, 0.0f, 0.0f);
        EXPECT_EQ(t.sample(ref, nan, nan), at_zero);
        EXPECT_EQ(t.sample(ref, inf, -inf), at_zero);
        for (float huge : {1e6f + 0.25f, -3e9f, 1e30f, -std::numeric_limits<float>::max(), 2147483648.0f}) {
            const glm::vec4 c = t.sample(ref, huge, 0.25f);
            for (int i = 0; i < 4; ++i) EXPECT_TRUE(c[i] >= 0.0f && c[i] <= 1.0f) << huge;
        }
    }
}

// ---------------------------------------------------------------------------
// KHR_texture_transform

TEST(TextureTransform, OffsetRotationAndScaleMapToTheExpectedTexel) {
    TestTextures t;
    const int32_t texture = t.add_grey(2, 2, {0, 51, 102, 255}, WF_WRAP_REPEAT, WF_WRAP_REPEAT, WF_TEXTURE_NEAREST);
    const auto with = [&](std::array<float, 6> m) {
        TextureRef ref = ref_to(texture);
        std::copy(m.begin(), m.end(), ref.transform);
        return ref;
    };
    // Offset: (0.25, 0.25) + (0.5, 0) lands in the top-right texel.
    EXPECT_FLOAT_EQ(t.sample(with(texture_transform(0.5f, 0, 0, 1, 1)), 0.25f, 0.25f).x * 255, kT10);
    // Scale: (0.375, 0.125) * 2 = (0.75, 0.25).
    EXPECT_FLOAT_EQ(t.sample(with(texture_transform(0, 0, 0, 2, 2)), 0.375f, 0.125f).x * 255, kT10);
    // Rotation by pi/2, the extension's matrix [cos sin; -sin cos]: (u, v) -> (v, -u);
    // (0.25, 0.75) -> (0.75, -0.25), which repeats to (0.75, 0.75).
    EXPECT_FLOAT_EQ(t.sample(with(texture_transform(0, 0, glm::half_pi<float>(), 1, 1)), 0.25f, 0.75f).x * 255, kT11);
    // All three: T * R * S, scale applied first.
    const std::array<float, 6> m = texture_transform(0.1f, 0.2f, 0.3f, 2.0f, 3.0f);
    const glm::mat3 T(1, 0, 0, 0, 1, 0, 0.1f, 0.2f, 1); // column-major
    const glm::mat3 R(std::cos(0.3f), -std::sin(0.3f), 0, std::sin(0.3f), std::cos(0.3f), 0, 0, 0, 1);
    const glm::mat3 S(2, 0, 0, 0, 3, 0, 0, 0, 1);
    const glm::vec3 expected = T * R * S * glm::vec3(0.4f, 0.7f, 1.0f);
    EXPECT_NEAR(m[0] * 0.4f + m[1] * 0.7f + m[2], expected.x, 1e-6f);
    EXPECT_NEAR(m[3] * 0.4f + m[4] * 0.7f + m[5], expected.y, 1e-6f);
}

// ---------------------------------------------------------------------------
// sRGB

double srgb_formula(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

TEST(TextureSrgb, TableHoldsTheNearestFloats) {
    for (int b = 0; b < 256; ++b) {
        const double exact = srgb_formula(b / 255.0);
        const float entry = srgb_to_linear_table[b];
        // No float lies closer to the exact value than the entry does.
        EXPECT_LE(std::abs(entry - exact), std::abs(std::nextafter(entry, 2.0f) - exact)) << b;
        EXPECT_LE(std::abs(entry - exact), std::abs(std::nextafter(entry, -1.0f) - exact)) << b;
    }
}

TEST(TextureSrgb, DecodeMatchesTheFormula) {
    // Through a texture: 8-bit texels, RGB decoded, alpha not.
    TestTextures t;
    for (int b = 0; b < 256; b += 5) {
        const int32_t texture = t.add(1, 1, {pack_rgba8(b, b, b, b)}, WF_WRAP_REPEAT, WF_WRAP_REPEAT, WF_TEXTURE_SRGB);
        const glm::vec4 c = t.sample(ref_to(texture), 0.5f, 0.5f);
        EXPECT_NEAR(c.x, srgb_formula(b / 255.0), 1e-6) << b;
        EXPECT_NEAR(c.w, b / 255.0, 1e-6) << b;
    }
}

TEST(TextureSrgb, FilteringHappensInLinearSpace) {
    // Black and white, halfway between their centres: half the light (0.5),
    // not the decode of the encoded average (about 0.214).
    TestTextures t;
    const TextureRef ref =
        ref_to(t.add_grey(2, 1, {0, 255}, WF_WRAP_CLAMP_TO_EDGE, WF_WRAP_CLAMP_TO_EDGE, WF_TEXTURE_SRGB));
    EXPECT_NEAR(t.sample(ref, 0.5f, 0.5f).x, 0.5f, 1e-6f);
    EXPECT_NEAR(t.sample(ref, 0.375f, 0.5f).x, 0.25f, 1e-6f);
}

// ---------------------------------------------------------------------------
// Host and device agree

const char* kSampleKernel = R"(
__kernel void sample_textures(__global const TextureInfo* infos, __global const uint* texels,
                              __global const TextureRef* refs, uint ref_count,
                              __global const float2* uv, __global float4* out, uint n) {
    const uint i = get_global_id(0);
    if (i >= n) return;
    out[i] = texture_sample(infos, texels, refs + i % ref_count, uv[i]);
}
)";

TEST(TextureDevice, HostAndPoclAgreeOnRandomUv) {
    std::mt19937 rng(11);
    std::uniform_int_distribution<uint32_t> byte(0, 255);
    const auto random_texels = [&](size_t n) {
        std::vector<uint32_t> v(n);
        for (uint32_t& x : v) x = pack_rgba8(byte(rng), byte(rng), byte(rng), byte(rng));
        return v;
    };
    TestTextures t;
    t.add(4, 4, random_texels(16), WF_WRAP_REPEAT, WF_WRAP_MIRRORED_REPEAT, WF_TEXTURE_SRGB);
    t.add(3, 5, random_texels(15), WF_WRAP_CLAMP_TO_EDGE, WF_WRAP_REPEAT);
    t.add(5, 3, random_texels(15), WF_WRAP_MIRRORED_REPEAT, WF_WRAP_CLAMP_TO_EDGE, WF_TEXTURE_NEAREST);
    t.add(7, 2, random_texels(14), WF_WRAP_MIRRORED_REPEAT, WF_WRAP_MIRRORED_REPEAT, WF_TEXTURE_SRGB);
    std::vector<TextureRef> refs;
    for (int32_t i = 0; i < 4; ++i) refs.push_back(ref_to(i));
    TextureRef transformed = ref_to(0);
    const std::array<float, 6> m = texture_transform(0.3f, -0.7f, 1.1f, 2.5f, -1.5f);
    std::copy(m.begin(), m.end(), transformed.transform);
    refs.push_back(transformed);
    refs.push_back(no_texture());

    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::uniform_real_distribution<float> small(-4.0f, 4.0f), large(-1e8f, 1e8f);
    std::vector<cl_float2> uv(1000);
    for (size_t i = 0; i < uv.size(); ++i) {
        const float specials[] = {nan, inf, -inf, 1e6f + 0.37f, -2.5e6f, 3e9f, -1e30f, 0.0f, 1.0f, 0.5f};
        const auto pick = [&](int k) { return k % 5 == 0 ? specials[i % 10] : (k % 5 == 1 ? large(rng) : small(rng)); };
        uv[i] = {{pick(int(i)), pick(int(i / 3))}};
    }

    const OpenClDevice& device = test::cpu_device();
    const cl::Program program =
        test::build_test_program(expand_kernel_source("materials/texture.h") + kSampleKernel);
    const auto buffer = [&](auto& v) {
        return cl::Buffer(device.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(v[0]), v.data());
    };
    cl::Buffer infos = buffer(t.infos), texels = buffer(t.texels), ref_buffer = buffer(refs), uv_buffer = buffer(uv);
    cl::Buffer out(device.context, CL_MEM_WRITE_ONLY, uv.size() * sizeof(cl_float4));
    cl::Kernel kernel(program, "sample_textures");
    kernel.setArg(0, infos);
    kernel.setArg(1, texels);
    kernel.setArg(2, ref_buffer);
    kernel.setArg(3, cl_uint(refs.size()));
    kernel.setArg(4, uv_buffer);
    kernel.setArg(5, out);
    kernel.setArg(6, cl_uint(uv.size()));
    device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1024), cl::NDRange(64));
    std::vector<cl_float4> on_device(uv.size());
    device.queue.enqueueReadBuffer(out, CL_TRUE, 0, on_device.size() * sizeof(cl_float4), on_device.data());

    double worst = 0;
    for (size_t i = 0; i < uv.size(); ++i) {
        const glm::vec4 host =
            texture_sample(t.infos.data(), t.texels.data(), &refs[i % refs.size()], glm::vec2(uv[i].s[0], uv[i].s[1]));
        for (int c = 0; c < 4; ++c) {
            ASSERT_TRUE(std::isfinite(on_device[i].s[c]) && on_device[i].s[c] >= 0.0f && on_device[i].s[c] <= 1.0f)
                << "uv " << uv[i].s[0] << ", " << uv[i].s[1];
            worst = std::max(worst, double(std::abs(host[c] - on_device[i].s[c])));
        }
    }
    EXPECT_LT(worst, 1e-5);
    test::report_measured("texture host vs PoCL: largest difference " + std::to_string(worst) + " over 1000 uv");
}

} // namespace
} // namespace wf
