/* generate — gives each free path slot the camera ray of its next sample.
 *
 * Slot i owns pixels i, i + pool, i + 2·pool, ... and runs through them sample
 * by sample: every sample of a pixel is traced by the same slot, one after the
 * other. Accumulation therefore needs no atomics and adds each pixel's samples
 * in sample order, so the image is independent of the pool size. A slot whose
 * samples are all started stays out of the queues. */
#include "path_state.h"
#include "wavefront/scene_types.h"
#include "common/sample_values.h"
#include "common/queue_push.h"

inline bool start_camera_sample(PathState* path, const RenderParams* params, const Camera* camera,
                                uint slot) {
    const uint work = path->work_done[slot];
    const uint pixels_owned = (params->pixel_count - 1u - slot) / params->pool_size + 1u;
    const uint sample = work / pixels_owned;
    if (sample >= params->spp) return false;
    const uint pixel = slot + (work % pixels_owned) * params->pool_size;

    const float4 u = sample_values(params, pixel, sample, 0u, WF_RNG_CAMERA);
    const float x = ((float)(pixel % camera->width) + u.x) / (float)camera->width;
    const float y = ((float)(pixel / camera->width) + u.y) / (float)camera->height;
    const float sx = (2.0f * x - 1.0f) * camera->tan_half_fov_y * camera->aspect;
    const float sy = (1.0f - 2.0f * y) * camera->tan_half_fov_y;
    const float3 direction = normalize(vload3(0, camera->forward) + sx * vload3(0, camera->right) +
                                       sy * vload3(0, camera->up));

    path->work_done[slot] = work + 1u;
    path->pixel[slot] = pixel;
    path->sample[slot] = sample;
    path->depth[slot] = 0u;
    path->ray_origin[slot] = (float4)(vload3(0, camera->origin), 0.0f);
    path->ray_direction[slot] = (float4)(direction, 0.0f);
    path->throughput[slot] = (float4)(1.0f, 1.0f, 1.0f, 0.0f);
    path->radiance[slot] = (float4)(0.0f);
    return true;
}

__kernel void generate(WF_STAGE_PARAMS, const Camera camera) {
    WF_BIND_PATH_STATE(path);
    __local uint scratch[2];
    uint slot;
    const bool started = queue_slot(params.pool_size, queues, counters, WF_QUEUE_REGENERATE, &slot) &&
                         start_camera_sample(&path, &params, &camera, slot);
    queue_push(queues, counters, params.pool_size, WF_QUEUE_EXTEND, slot, started, scratch);
}
