/* generate — gives each free path slot the camera ray of its next sample.
 *
 * Each slot owns every pool-th pixel of those traced and runs through them
 * sample by sample (nth_sample, kernels/path_view.h): every sample of a pixel
 * is traced by the same slot, one after the other. Accumulation therefore needs no atomics and adds each pixel's samples
 * in sample order, so the image is independent of the pool size. A slot whose
 * samples are all started stays out of the queues. */
#ifndef WF_STAGE_GENERATE_H
#define WF_STAGE_GENERATE_H

#include "wavefront/compat.h"
#include "path_view.h"
#include "wavefront/scene_types.h"
#include "common/sample_values.h"
#include "stages/stage_step.h"
#include "lanes/lanes.h"

#define WF_W 1
#include "lanes/lane_width.inc"
#include "stages/camera_ray.inc"
#undef WF_W

/* Begins the slot's next sample, if it has one left: its path state but for
 * its camera ray (write_camera_ray). Returns whether it had one. */
WF_INLINE bool begin_camera_sample(PathState* path, const RenderParams* params, uint slot) {
    const uint work = path_samples_started(path, slot);
    if (nth_sample(path, params, slot, work).sample >= params->spp) return false;
    set_path_throughput(path, slot, (float3)(1.0f), 0u); /* no bounce yet */
    start_path_radiance(path, slot, work + 1u);
    return true;
}

/* The camera ray of the sample the slot began, into its ray. */
WF_INLINE void write_camera_ray(PathState* path, const RenderParams* params, const Camera* camera, uint slot) {
    const PathSample s = current_sample(path, params, slot);
    const float4 u = sample_values(params, s.pixel, s.sample, 0u, WF_RNG_CAMERA);
    path->ray_origin[slot] = (float4)(vload3(0, camera->origin), 0.0f);
    path->ray_direction[slot] = (float4)(vec_to_float3(camera_direction_x1(camera, s.pixel, u.x, u.y)), 0.0f);
}

WF_INLINE bool start_camera_sample(PathState* path, const RenderParams* params, const Camera* camera,
                                uint slot) {
    if (!begin_camera_sample(path, params, slot)) return false;
    write_camera_ray(path, params, camera, slot);
    return true;
}

/* The slot's next camera sample into the extension queue, if it has one left. */
WF_FORCE_INLINE uint generate_step(const StageView* v, uint slot, StageTally* t) {
    if (!start_camera_sample(v->path, v->params, v->camera, slot)) return WF_QUEUE_COUNT;
    ++t->started;
    return WF_QUEUE_EXTEND;
}

#endif
