/* generate_lanes.h — the group schedule's camera rays, a run of lanes a
 * work-item: the slots whose samples begin_camera_sample began
 * (stages/generate.h) get their sample numbers (lane_sample_values,
 * stages/shade_lanes.h) and their directions (stages/camera_ray.inc) in
 * lanes, just before intersect traces them as a packet, with the bits
 * write_camera_ray gives them a path at a time. Device only. */
#ifndef WF_GENERATE_LANES_H
#define WF_GENERATE_LANES_H

#include "wavefront/compat.h"
#include "stages/generate.h"
#include "stages/shade_lanes.h"

/* On a CPU, whose intersect work-items take a run of eight camera rays; a
 * GPU's take one or two, for which lanes would cost more than they save. */
#if defined(WF_GROUP_LANES) && !WF_GPU_TRAVERSAL
#define WF_CAMERA_RAYS_IN_LANES 1
#if WF_TRACE_SLOTS > WF_LANE_WIDTH
#error "a run of camera rays (WF_TRACE_SLOTS) must fit the lanes"
#endif
#define WF_W WF_LANE_WIDTH
#include "lanes/lane_width.inc"
#include "stages/camera_ray.inc"

/* write_camera_ray for slot[0 .. count), count at most WF_LANE_WIDTH; lanes
 * past `count` repeat the first slot and are not written. */
WF_INLINE void write_camera_rays(PathState* path, const RenderParams* params, const Camera* camera, const uint* slot,
                                 uint count) {
    uint pixel[WF_W], sample[WF_W];
    for (uint i = 0u; i < WF_W; ++i) {
        const PathSample s = current_sample(path, params, slot[i < count ? i : 0u]);
        pixel[i] = s.pixel;
        sample[i] = s.sample;
    }
    const LUINT p = WF_CAT(vload, WF_W)(0, pixel);
    LREAL u[4];
    LFN(lane_sample_values)(params, p, WF_CAT(vload, WF_W)(0, sample), (LUINT)(0u), WF_RNG_CAMERA, u);
    const LVEC d = LFN(camera_direction)(camera, p, u[0], u[1]);
    float x[WF_W], y[WF_W], z[WF_W];
    WF_CAT(vstore, WF_W)(d.x, 0, x);
    WF_CAT(vstore, WF_W)(d.y, 0, y);
    WF_CAT(vstore, WF_W)(d.z, 0, z);
    const float4 origin = (float4)(vload3(0, camera->origin), 0.0f);
    for (uint i = 0u; i < count; ++i) {
        path->ray_origin[slot[i]] = origin;
        path->ray_direction[slot[i]] = (float4)(x[i], y[i], z[i], 0.0f);
    }
}

#undef WF_W
#else
#define WF_CAMERA_RAYS_IN_LANES 0
#endif
#endif
