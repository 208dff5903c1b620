/* trace_width.h — how many rays one work-item of a ray-tracing stage
 * (intersect, intersect_shadow, and their part of the group schedule)
 * traces at once: 1, or 2 where the host asks (-DWF_TRACE_WIDTH=2,
 * --trace-width; by default on a CPU when the scene's triangles outgrow the
 * device's cache: host/render/device_renderer.cpp). Two rays' traversals take
 * turns (bvh_traverse_pair in geometry/bvh_traverse.h), so that one ray's
 * next node is on its way from memory while the other's is tested, where a
 * lone ray waits for every load its last test chose; on a scene that fits the
 * cache there is no such wait, and taking turns only costs. A GPU hides the
 * wait by running other warps. */
#ifndef WF_TRACE_WIDTH_H
#define WF_TRACE_WIDTH_H

#ifndef WF_TRACE_WIDTH
#define WF_TRACE_WIDTH 1
#endif

/* The slots one work-item of intersect takes: on a CPU, eight, so that rays
 * from one point (camera rays) can go as a packet (geometry/bvh_packet.h),
 * the others WF_TRACE_WIDTH at a time; on a GPU, WF_TRACE_WIDTH. */
#if WF_GPU_TRAVERSAL
#define WF_TRACE_SLOTS WF_TRACE_WIDTH
#else
#define WF_TRACE_SLOTS 8
#endif

#endif
