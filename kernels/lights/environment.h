/* environment.h — light from infinitely far away: an equirectangular map
 * importance-sampled by luminance, or a constant radiance; shared by the
 * kernels and the host (host/scene/environment_map.h builds the buffers).
 *
 * Mapping (map frame, +y up as in glTF): texel (col, row) covers
 *   phi   in 2pi [col, col + 1) / width  - pi,   theta in pi [row, row + 1) / height,
 *   direction = (sin theta sin phi, cos theta, -sin theta cos phi),
 * so row 0 is the zenith, the image's centre column looks down -z and columns
 * run toward +x. The world sees the map turned about +y by the rotation
 * angle a: world = R_y(a) map, with R_y(a) (x, y, z) = (x cos a + z sin a, y,
 * -x sin a + z cos a).
 *
 * Lookup is nearest-texel, not bilinear: then the radiance is constant over
 * each texel exactly as the sampling density is, and a texel given no
 * probability (a black one) has no light that filtering could spill into it.
 *
 * Sampling: a row by the marginal CDF, a texel in it by that row's CDF (both
 * inverted continuously, so stratified numbers stay stratified), then a point
 * uniform in solid angle over the texel (phi linear, cos theta linear). Each
 * texel's probability is its luminance times its solid angle, so the density
 * in solid angle is constant over a texel and stored with it: finite at the
 * poles, and exactly 1 / 4pi for a constant map.
 *
 * Promises: environment_sample returns radiance and pdf as environment_radiance
 * and environment_pdf give them for its direction, by calling them (bit for
 * bit the same); the pdf is 0 where the sample is unusable. */
#ifndef WF_ENVIRONMENT_H
#define WF_ENVIRONMENT_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"

#ifndef WF_PI
#define WF_PI 3.14159265358979323846f
#endif

WF_DEVICE_BEGIN

typedef struct EnvironmentSample {
    float3 direction; /* unit, world space, from the receiver toward the environment */
    float3 radiance;  /* arriving from that direction */
    float pdf;        /* solid angle; 0 when unusable */
} EnvironmentSample;

/* World direction into the map frame. */
WF_INLINE float3 environment_to_map(Environment env, float3 d) {
    return make_float3(d.x * env.cos_rotation - d.z * env.sin_rotation, d.y,
                       d.x * env.sin_rotation + d.z * env.cos_rotation);
}

WF_INLINE float3 environment_from_map(Environment env, float3 d) {
    return make_float3(d.x * env.cos_rotation + d.z * env.sin_rotation, d.y,
                       -d.x * env.sin_rotation + d.z * env.cos_rotation);
}

/* The texel a unit world direction falls in, row-major. */
WF_INLINE uint32_t environment_texel(Environment env, float3 direction) {
    const float3 d = environment_to_map(env, direction);
    const float u = atan2(d.x, -d.z) * (0.5f / WF_PI) + 0.5f;
    const float v = acos(clamp(d.y, -1.0f, 1.0f)) * (1.0f / WF_PI);
    const uint32_t col = (uint32_t)min(max(u * (float)env.width, 0.0f), (float)(env.width - 1u));
    const uint32_t row = (uint32_t)min(max(v * (float)env.height, 0.0f), (float)(env.height - 1u));
    return row * env.width + col;
}

/* Radiance arriving from unit world direction `direction`. */
WF_INLINE float3 environment_radiance(Environment env, WF_GLOBAL const float* texels, float3 direction) {
    const float3 scale = make_float3(env.scale[0], env.scale[1], env.scale[2]);
    if (env.flags & WF_ENVIRONMENT_CONSTANT) return scale;
    const uint32_t t = environment_texel(env, direction);
    return scale * make_float3(texels[4u * t], texels[4u * t + 1u], texels[4u * t + 2u]);
}

/* Solid-angle density with which environment_sample picks unit `direction`. */
WF_INLINE float environment_pdf(Environment env, WF_GLOBAL const float* texels, float3 direction) {
    if (env.flags & WF_ENVIRONMENT_CONSTANT) return 0.25f / WF_PI;
    return texels[4u * environment_texel(env, direction) + 3u];
}

/* The interval i in [0, n) with cdf[i] <= u < cdf[i + 1], cdf having n + 1
 * entries from 0 to 1; among equal entries (intervals of no probability) the
 * last, which begins the next interval that has some. */
WF_INLINE uint32_t environment_find_interval(WF_GLOBAL const float* cdf, uint32_t n, float u) {
    uint32_t lo = 0u, hi = n; /* cdf[lo] <= u holds throughout (cdf[0] = 0) */
    while (hi - lo > 1u) {
        const uint32_t mid = (lo + hi) / 2u;
        if (cdf[mid] <= u) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* Where u lies within [cdf[i], cdf[i + 1]), in [0, 1]. */
WF_INLINE float environment_offset(WF_GLOBAL const float* cdf, uint32_t i, float u) {
    const float width = cdf[i + 1u] - cdf[i];
    return width > 0.0f ? clamp((u - cdf[i]) / width, 0.0f, 1.0f) : 0.5f;
}

/* A direction toward the environment from two uniform numbers in [0, 1).
 * `distribution` holds the marginal CDF over rows (height + 1 floats), then
 * each row's CDF over its texels (width + 1 floats each). */
WF_INLINE EnvironmentSample environment_sample(Environment env, WF_GLOBAL const float* texels,
                                               WF_GLOBAL const float* distribution, float2 u) {
    EnvironmentSample s;
    float z, phi;
    if (env.flags & WF_ENVIRONMENT_CONSTANT) {
        z = 1.0f - 2.0f * u.x;
        phi = 2.0f * WF_PI * u.y - WF_PI;
    } else {
        const uint32_t w = env.width, h = env.height;
        const uint32_t row = environment_find_interval(distribution, h, u.y);
        const float dv = environment_offset(distribution, row, u.y);
        WF_GLOBAL const float* row_cdf = distribution + (h + 1u) + row * (w + 1u);
        const uint32_t col = environment_find_interval(row_cdf, w, u.x);
        const float du = environment_offset(row_cdf, col, u.x);
        const float z_top = cos(WF_PI * (float)row / (float)h);
        const float z_bottom = cos(WF_PI * (float)(row + 1u) / (float)h);
        z = z_top + dv * (z_bottom - z_top);
        phi = 2.0f * WF_PI * (((float)col + du) / (float)w) - WF_PI;
    }
    const float r = sqrt(max(0.0f, 1.0f - z * z));
    const float3 in_map = make_float3(r * sin(phi), z, -r * cos(phi));
    s.direction = environment_from_map(env, in_map);
    s.radiance = environment_radiance(env, texels, s.direction);
    s.pdf = environment_pdf(env, texels, s.direction);
    return s;
}

WF_DEVICE_END

#endif
