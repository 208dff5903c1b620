/* lanes.h — the types of code written once for any lane width: a real, an
 * integer (also the mask: a comparison's result), a colour and a direction,
 * one of each per lane, at width 1 (a path a work-item: the megakernel, the
 * global-queue schedules, GPUs) and at 8 and 16 (eight or sixteen paths a
 * work-item in float8/float16 lanes: the group schedule on a CPU).
 *
 * Colours and directions are structures of three reals, so that one lane's
 * arithmetic is the same IEEE operations in the same order at every width:
 * the same bits. Such code lives in .inc files, which the kernel source
 * expander (host/device/kernel_sources.cpp) expands at every #include; each
 * is included once per width with WF_W set, after lanes/lane_width.inc, which
 * names the types and operations of that width (LREAL, LRGB, LFN(name), ...).
 * Device only. */
#ifndef WF_LANES_H
#define WF_LANES_H

#include "wavefront/compat.h"

#define WF_CAT_(a, b) a##b
#define WF_CAT(a, b) WF_CAT_(a, b)

/* The 4-byte words a struct takes: the stride of a gather of one of its
 * fields across an array of them, from the first element's. */
#define WF_WORDS(S) ((int)(sizeof(S) / 4u))

typedef float lreal1;
typedef int lint1;
typedef float8 lreal8;
typedef int8 lint8;
typedef float16 lreal16;
typedef int16 lint16;
typedef uint luint1;
typedef uint8 luint8;
typedef uint16 luint16;

#define WF_LANE_STRUCTS(w)                  \
    typedef struct lrgb##w {                \
        lreal##w r, g, b;                   \
    } lrgb##w;                              \
    typedef struct lvec##w {                \
        lreal##w x, y, z;                   \
    } lvec##w;
WF_LANE_STRUCTS(1)
WF_LANE_STRUCTS(8)
WF_LANE_STRUCTS(16)
#undef WF_LANE_STRUCTS

/* One lane of a width-1 colour or direction as the scalar code's float3. */
WF_INLINE float3 rgb_to_float3(lrgb1 c) { return (float3)(c.r, c.g, c.b); }
WF_INLINE lrgb1 rgb_from_float3(float3 c) {
    lrgb1 r = {c.x, c.y, c.z};
    return r;
}
WF_INLINE float3 vec_to_float3(lvec1 v) { return (float3)(v.x, v.y, v.z); }
WF_INLINE lvec1 vec_from_float3(float3 v) {
    lvec1 r = {v.x, v.y, v.z};
    return r;
}

#endif
