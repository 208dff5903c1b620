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

WF_INLINE bool start_camera_sample(PathState* path, const RenderParams* params, const Camera* camera,
                                uint slot) {
    const uint work = path_samples_started(path, slot);
    const PathSample next = nth_sample(path, params, slot, work);
    if (next.sample >= params->spp) return false;
    const uint pixel = next.pixel;

    const float4 u = sample_values(params, pixel, next.sample, 0u, WF_RNG_CAMERA);
    const float x = ((float)(pixel % camera->width) + u.x) / (float)camera->width;
    const float y = ((float)(pixel / camera->width) + u.y) / (float)camera->height;
    const float sx = (2.0f * x - 1.0f) * camera->tan_half_fov_y * camera->aspect;
    const float sy = (1.0f - 2.0f * y) * camera->tan_half_fov_y;
    const float3 direction = normalize(vload3(0, camera->forward) + sx * vload3(0, camera->right) +
                                       sy * vload3(0, camera->up));

    path->ray_origin[slot] = (float4)(vload3(0, camera->origin), 0.0f);
    path->ray_direction[slot] = (float4)(direction, 0.0f);
    set_path_throughput(path, slot, (float3)(1.0f), 0u); /* no bounce yet */
    start_path_radiance(path, slot, work + 1u);
    return true;
}

/* The slot's next camera sample into the extension queue, if it has one left. */
WF_FORCE_INLINE uint generate_step(const StageView* v, uint slot, StageTally* t) {
    if (!start_camera_sample(v->path, v->params, v->camera, slot)) return WF_QUEUE_COUNT;
    ++t->started;
    return WF_QUEUE_EXTEND;
}

#endif
