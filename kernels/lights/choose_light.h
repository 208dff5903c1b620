/* choose_light.h — next-event estimation over every light in the scene: one
 * entry of the alias table, chosen by power (host/device/device_scene.cpp), then a
 * sample of that light by its kind. The returned pdf includes the choice.
 * The choice and emissive triangles are lights/light_lanes.inc's, at width 1. */
#ifndef WF_CHOOSE_LIGHT_H
#define WF_CHOOSE_LIGHT_H

#include "wavefront/compat.h"
#include "wavefront/render_params.h"
#include "compiled_features.h"
#include "scene_view.h"
#include "lights/light_sample.h"
#include "lights/environment.h"
#include "lights/punctual.h"
#include "geometry/float_error.h"
#include "materials/alpha_mask.h"
#include "materials/surface_material.h"
#include "lanes/lanes.h"

#define WF_W 1
#include "lanes/lane_width.inc"
#include "lights/light_lanes.inc"
#undef WF_W

WF_INLINE LightSample light_sample_from_x1(const LightSample_x1* l) {
    LightSample s;
    s.wi = vec_to_float3(l->wi);
    s.radiance = rgb_to_float3(l->radiance);
    s.pdf = l->pdf;
    s.delta = l->delta != 0;
    s.segment_end = (uint)l->segment_end;
    s.point = vec_to_float3(l->point);
    s.point_error = vec_to_float3(l->point_error);
    s.normal = vec_to_float3(l->normal);
    return s;
}

/* u.x and u.w choose the light; u.y and u.z place the sample on it. */
WF_INLINE LightSample sample_light(const RenderParams* params, const Scene* scene, float3 receiver, float4 u) {
    const int chosen = choose_light_x1(scene->lights, params->light_count, u.x, u.w);
    const LightEntry entry = scene->lights[chosen];
#if WF_HAS_EMISSIVE_TRIANGLES
    if (entry.kind == WF_LIGHT_TRIANGLE) {
        const LightSample_x1 s = sample_emissive_triangle_x1(scene, chosen, vec_from_float3(receiver), u.y, u.z);
        return light_sample_from_x1(&s);
    }
#endif
    LightSample s = no_light_sample();
#if WF_HAS_PUNCTUAL_LIGHTS
    if (entry.kind == WF_LIGHT_PUNCTUAL) {
        const PunctualLight light = scene->punctual[entry.index];
        const PunctualSample p = punctual_sample(light, receiver);
        s.wi = p.direction;
        s.radiance = p.Li;
        s.pdf = entry.pmf;
        s.delta = true;
        s.segment_end = light.type == WF_PUNCTUAL_DIRECTIONAL ? WF_SEGMENT_TO_INFINITY : WF_SEGMENT_TO_POINT;
        s.point = vload3(0, light.position);
        return s;
    }
#endif
#if WF_HAS_ENVIRONMENT
    if (entry.kind == WF_LIGHT_ENVIRONMENT) {
        const EnvironmentSample e =
            environment_sample(params->environment, scene->environment_texels, scene->environment_distribution, u.yz);
        s.wi = e.direction;
        s.radiance = e.radiance;
        s.pdf = entry.pmf * e.pdf;
    }
#endif
    return s;
}

#endif
