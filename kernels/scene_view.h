/* scene_view.h — the scene's buffers (include/wavefront/scene_buffers.h) gathered
 * into one Scene, which stage functions, light sampling, textures and the
 * BVH's hit filter take as one argument. Device only. */
#ifndef WF_KERNEL_SCENE_H
#define WF_KERNEL_SCENE_H

#include "wavefront/scene_buffers.h"

#define WF_SCENE_MEMBER(type, name, what) __global const type* name;
typedef struct Scene {
    WF_SCENE_BUFFERS(WF_SCENE_MEMBER)
#if WF_GPU_TRAVERSAL
    /* A GPU's traversal stacks, in local memory (geometry/bvh_traverse.h). */
    __local uint* traversal_nodes;
    __local uchar* traversal_slots;
#endif
} Scene;
#undef WF_SCENE_MEMBER

#endif
