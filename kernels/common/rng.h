/* rng.h — counter-based random numbers.
 *
 * Every random number is a pure function of (seed, pixel, sample, bounce,
 * dimension group), hashed with pcg4d (Jarzynski and Olano, "Hash Functions for
 * GPU Rendering", JCGT 2020). No generator state travels with a path, so the
 * image does not depend on the pool size, the local size or the order in which
 * paths are processed. Each group yields four numbers in [0, 1). */
#ifndef WF_RNG_H
#define WF_RNG_H

#include "wavefront/compat.h"

/* Dimension groups used at each bounce; fixed, whatever the scene's features,
 * so that variants of the kernels draw the same numbers for the same path. */
#define WF_RNG_CAMERA 0 /* x: pixel jitter x, y: pixel jitter y */
#define WF_RNG_LIGHT 1  /* x: light choice, w: its alias; y, z: point on the light */
#define WF_RNG_BSDF 2   /* x: lobe; y, z: direction; w: roulette (handed on in ray_origin.w) */
#define WF_RNG_GROUPS 3

/* pcg4d on four words x, y, z, w, each a uint or a lane vector of them
 * (common/rng_lanes.inc hashes eight keys at once with it). */
#define WF_PCG4D(x, y, z, w)            \
    do {                                \
        x = x * 1664525u + 1013904223u; \
        y = y * 1664525u + 1013904223u; \
        z = z * 1664525u + 1013904223u; \
        w = w * 1664525u + 1013904223u; \
        x += y * w;                     \
        y += z * x;                     \
        z += x * y;                     \
        w += y * z;                     \
        x ^= x >> 16u;                  \
        y ^= y >> 16u;                  \
        z ^= z >> 16u;                  \
        w ^= w >> 16u;                  \
        x += y * w;                     \
        y += z * x;                     \
        z += x * y;                     \
        w += y * z;                     \
    } while (0)

WF_INLINE uint4 pcg4d(uint4 v) {
    WF_PCG4D(v.x, v.y, v.z, v.w);
    return v;
}

/* 24 random bits scaled into [0, 1): exactly representable, never 1. */
WF_INLINE float4 rng_uniform4(uint seed, uint pixel, uint sample, uint bounce, uint group) {
    const uint4 bits = pcg4d((uint4)(pixel, sample, bounce * WF_RNG_GROUPS + group, seed));
    return convert_float4(bits >> 8u) * (1.0f / 16777216.0f);
}

#endif
