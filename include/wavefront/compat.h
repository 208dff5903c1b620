/* compat.h — the small common language of code shared by the host (C++17) and
 * the kernels (OpenCL C 1.2). Shared device code sits between WF_DEVICE_BEGIN
 * and WF_DEVICE_END.
 *
 * Shared code is written against this vocabulary: fixed-width integers, float2
 * with make_float2, float3 with dot/cross/normalize/min/max, make_float3, float4
 * with make_float4, as_uint/as_float, the scalar clamp, sqrt, sin, cos, sinpi,
 * cospi, acos, atan2, floor, pow, exp, exp2, log, log2 and copysign, clz, and WF_GLOBAL for the address space of
 * scene buffers, WF_CONSTANT for tables at program scope. For SIMD inside a
 * work-item (the BVH traversal): float4 and
 * int4 lanes with their arithmetic, max and fabs, the relational
 * built-ins isless, isgreater, islessequal and isequal (-1 or 0 per lane),
 * select, vload4 and vstore4; uint4 lanes (make_uint4) with their integer
 * arithmetic, for a Sobol point's four coordinates; float8 lanes minus or times a scalar, min, max,
 * islessequal (int8), vload8 and vstore8; and lane_bits4/8, the one helper
 * OpenCL lacks: bit i set where lane i is true. On the device these are the
 * OpenCL built-ins; on the host they map onto GLM, <cmath> and <cstring>, and
 * float8 onto an array computed lane by lane: the same IEEE operations, so the
 * same bits. WF_FORCE_INLINE and WF_PREFETCH serve the traversal's inner loop
 * (and WF_FORCE_INLINE the kernels' barrier-holding helpers and stage steps).
 * Nothing else belongs here. */
#ifndef WAVEFRONT_COMPAT_H
#define WAVEFRONT_COMPAT_H

#ifdef __OPENCL_C_VERSION__

typedef uint uint32_t;
typedef int int32_t;
#define WF_GLOBAL __global
#define WF_CONSTANT __constant
/* Device functions are WF_INLINE: C99's plain inline on a CPU device, static
 * inline where the host asks for it (WF_STATIC_FUNCTIONS, for GPUs). Plain
 * inline leaves no definition wherever the compiler declines to inline, which
 * a GPU's linker rejects (bench/gpu_isa.py links each program for AMD GPUs);
 * static fixes that, but made PoCL's renders 10-32% slower, its inliner then
 * leaving large functions as calls. WF_FORCE_INLINE serves the traversal's
 * inner loop, which PoCL's inliner otherwise leaves as calls, and the
 * functions that hold barriers (common/queue_push.h) or only pass a step on
 * (stages/stage_step.h). WF_GPU_INLINE
 * serves the stages' large steps, which take the kernel's views (path state,
 * scene, parameters) by pointer: a GPU's compiler left as a call keeps those
 * views in scratch memory (up to 984 bytes a lane on gfx90a), so a GPU's
 * program inlines them outright; PoCL's choice is left alone, since forcing
 * them slowed the Cornell box's group schedule by 3%
 * (bench/results/gpu-isa.md). */
#ifdef WF_STATIC_FUNCTIONS
#define WF_INLINE static inline
#define WF_FORCE_INLINE static inline __attribute__((always_inline))
#define WF_GPU_INLINE WF_FORCE_INLINE
#else
#define WF_INLINE inline
#define WF_FORCE_INLINE inline __attribute__((always_inline))
#define WF_GPU_INLINE WF_INLINE
#endif
/* OpenCL's prefetch() does nothing on PoCL; clang's builtin does, on a CPU,
 * where every address space is one. A GPU's compiler (NVIDIA's) refuses a
 * __global pointer for its generic one; a GPU has no use for it. */
#if defined(__clang__) && (defined(__x86_64__) || defined(__aarch64__))
#define WF_PREFETCH(p) __builtin_prefetch(p)
#else
#define WF_PREFETCH(p)
#endif
#define make_float2(x, y) ((float2)((x), (y)))
#define make_float3(x, y, z) ((float3)((x), (y), (z)))
#define make_float4(x, y, z, w) ((float4)((x), (y), (z), (w)))
#define make_uint4(x, y, z, w) ((uint4)((x), (y), (z), (w)))
#define WF_DEVICE_BEGIN
#define WF_DEVICE_END
WF_INLINE float3 load_float3(WF_GLOBAL const float* p) { return vload3(0, p); }
#ifdef __AVX__ /* an x86 CPU device, as PoCL's: one movmskps, where LLVM would shuffle */
WF_INLINE uint lane_bits4(int4 m) { return (uint)__builtin_ia32_movmskps(as_float4(m)); }
WF_INLINE uint lane_bits8(int8 m) { return (uint)__builtin_ia32_movmskps256(as_float8(m)); }
#else
WF_INLINE uint lane_bits4(int4 m) { return (uint)((m.x & 1) | (m.y & 2) | (m.z & 4) | (m.w & 8)); }
WF_INLINE uint lane_bits8(int8 m) { return lane_bits4(m.lo) | lane_bits4(m.hi) << 4; }
#endif

#else /* host C++ */

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>

#define WF_GLOBAL
#define WF_CONSTANT static const
#define WF_INLINE inline
#define WF_FORCE_INLINE inline
#define WF_GPU_INLINE inline
#define WF_PREFETCH(p) __builtin_prefetch(p)

namespace wf_compat {
using float2 = glm::vec2;
inline float2 make_float2(float x, float y) { return float2(x, y); }
using float3 = glm::vec3;
inline float3 make_float3(float x, float y, float z) { return float3(x, y, z); }
using float4 = glm::vec4;
inline float4 make_float4(float x, float y, float z, float w) { return float4(x, y, z, w); }
inline float as_float(uint32_t bits) { float f; std::memcpy(&f, &bits, 4); return f; }
inline uint32_t as_uint(float f) { uint32_t bits; std::memcpy(&bits, &f, 4); return bits; }
inline float3 load_float3(const float* p) { return float3(p[0], p[1], p[2]); }
/* OpenCL's scalar min/max; fmin/fmax stay NaN-aware on both sides. */
inline float min(float a, float b) { return a < b ? a : b; }
inline float max(float a, float b) { return a > b ? a : b; }
/* Their componentwise float3 forms, and fabs on float3. */
inline float3 min(float3 a, float3 b) { return float3(min(a.x, b.x), min(a.y, b.y), min(a.z, b.z)); }
inline float3 max(float3 a, float3 b) { return float3(max(a.x, b.x), max(a.y, b.y), max(a.z, b.z)); }
inline float3 fabs(float3 v) { return glm::abs(v); }
using glm::cross;
using glm::dot;
using glm::normalize;
using std::fabs; /* its float overload, beside the float3 one above */
using std::nextafter; /* and INFINITY from <cmath>: as in OpenCL C */
/* The float overloads of the math built-ins that shared code uses (never the
 * double ones that unqualified calls could otherwise find). */
inline float clamp(float x, float lo, float hi) { return min(max(x, lo), hi); }
using std::acos;
using std::atan2;
using std::copysign;
using std::cos;
using std::exp;
using std::exp2;
using std::floor;
using std::log;
using std::log2;
using std::pow;
using std::sin;
using std::sqrt;
/* sin(pi x) and cos(pi x). The device's need no argument reduction (PoCL's
 * sin and cos always call one); the host's are sin and cos of the rounded
 * product, as the shared code computed before it had these. */
inline float sinpi(float x) { return std::sin(static_cast<float>(M_PI) * x); }
inline float cospi(float x) { return std::cos(static_cast<float>(M_PI) * x); }
inline uint32_t clz(uint32_t x) { return x == 0 ? 32u : static_cast<uint32_t>(__builtin_clz(x)); }

/* Four lanes: GLM's arithmetic, and the built-ins it lacks. */
using int4 = glm::ivec4;
using uint4 = glm::uvec4;
inline uint4 make_uint4(uint32_t x, uint32_t y, uint32_t z, uint32_t w) { return uint4(x, y, z, w); }
inline float4 max(float4 a, float4 b) { return float4(max(a.x, b.x), max(a.y, b.y), max(a.z, b.z), max(a.w, b.w)); }
inline float4 fabs(float4 v) { return glm::abs(v); }
inline int4 lanes_true(bool x, bool y, bool z, bool w) { return -int4(x, y, z, w); }
inline int4 isless(float4 a, float4 b) { return lanes_true(a.x < b.x, a.y < b.y, a.z < b.z, a.w < b.w); }
inline int4 isgreater(float4 a, float4 b) { return isless(b, a); }
inline int4 islessequal(float4 a, float4 b) { return lanes_true(a.x <= b.x, a.y <= b.y, a.z <= b.z, a.w <= b.w); }
inline int4 isequal(float4 a, float4 b) { return lanes_true(a.x == b.x, a.y == b.y, a.z == b.z, a.w == b.w); }
inline float4 select(float4 a, float4 b, int4 c) {
    return float4(c.x < 0 ? b.x : a.x, c.y < 0 ? b.y : a.y, c.z < 0 ? b.z : a.z, c.w < 0 ? b.w : a.w);
}
inline uint32_t lane_bits4(int4 m) { return static_cast<uint32_t>((m.x & 1) | (m.y & 2) | (m.z & 4) | (m.w & 8)); }
inline float4 vload4(size_t offset, const float* p) {
    return float4(p[4 * offset], p[4 * offset + 1], p[4 * offset + 2], p[4 * offset + 3]);
}
inline void vstore4(float4 v, size_t offset, float* p) {
    for (int i = 0; i < 4; ++i) p[4 * offset + i] = v[i];
}

/* Eight lanes, one array element each. */
struct float8 {
    float s[8];
};
struct int8 {
    int32_t s[8];
};
template <class F> float8 lanewise(F f) {
    float8 r;
    for (int i = 0; i < 8; ++i) r.s[i] = f(i);
    return r;
}
template <class F> int8 lanes_true8(F f) {
    int8 r;
    for (int i = 0; i < 8; ++i) r.s[i] = f(i) ? -1 : 0;
    return r;
}
inline float8 operator-(float8 a, float b) { return lanewise([&](int i) { return a.s[i] - b; }); }
inline float8 operator*(float8 a, float b) { return lanewise([&](int i) { return a.s[i] * b; }); }
inline float8 min(float8 a, float8 b) { return lanewise([&](int i) { return min(a.s[i], b.s[i]); }); }
inline float8 max(float8 a, float8 b) { return lanewise([&](int i) { return max(a.s[i], b.s[i]); }); }
inline float8 min(float8 a, float b) { return lanewise([&](int i) { return min(a.s[i], b); }); }
inline float8 max(float8 a, float b) { return lanewise([&](int i) { return max(a.s[i], b); }); }
inline int8 islessequal(float8 a, float8 b) { return lanes_true8([&](int i) { return a.s[i] <= b.s[i]; }); }
inline uint32_t lane_bits8(int8 m) {
    uint32_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= static_cast<uint32_t>(m.s[i] & 1) << i;
    return bits;
}
inline float8 vload8(size_t offset, const float* p) { return lanewise([&](int i) { return p[8 * offset + i]; }); }
inline void vstore8(float8 v, size_t offset, float* p) {
    for (int i = 0; i < 8; ++i) p[8 * offset + i] = v.s[i];
}
} // namespace wf_compat

/* Device code compiled for the host lives in namespace wf_device, so its names
 * (float3, min, dot, ...) never leak into host code that includes it. */
#define WF_DEVICE_BEGIN namespace wf_device { using namespace wf_compat;
#define WF_DEVICE_END }

#endif

#endif /* WAVEFRONT_COMPAT_H */
