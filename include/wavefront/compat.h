/* compat.h — the small common language of code shared by the host (C++17) and
 * the kernels (OpenCL C 1.2). Shared device code sits between WF_DEVICE_BEGIN
 * and WF_DEVICE_END.
 *
 * Shared code is written against this vocabulary: fixed-width integers, float2
 * with make_float2, float3 with dot/cross/normalize/min/max, make_float3, float4
 * with make_float4, as_uint/as_float, the scalar clamp, sqrt, sin, cos, acos,
 * atan2, floor, pow and copysign, and WF_GLOBAL for the address space of scene
 * buffers. On the device these are the OpenCL built-ins; on the host they map
 * onto GLM, <cmath> and <cstring>. Nothing else belongs here. */
#ifndef WAVEFRONT_COMPAT_H
#define WAVEFRONT_COMPAT_H

#ifdef __OPENCL_C_VERSION__

typedef uint uint32_t;
typedef int int32_t;
#define WF_GLOBAL __global
#define WF_INLINE inline
#define make_float2(x, y) ((float2)((x), (y)))
#define make_float3(x, y, z) ((float3)((x), (y), (z)))
#define make_float4(x, y, z, w) ((float4)((x), (y), (z), (w)))
#define WF_DEVICE_BEGIN
#define WF_DEVICE_END
WF_INLINE float3 load_float3(WF_GLOBAL const float* p) { return vload3(0, p); }

#else /* host C++ */

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>

#define WF_GLOBAL
#define WF_INLINE inline

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
using std::floor;
using std::pow;
using std::sin;
using std::sqrt;
} // namespace wf_compat

/* Device code compiled for the host lives in namespace wf_device, so its names
 * (float3, min, dot, ...) never leak into host code that includes it. */
#define WF_DEVICE_BEGIN namespace wf_device { using namespace wf_compat;
#define WF_DEVICE_END }

#endif

#endif /* WAVEFRONT_COMPAT_H */
