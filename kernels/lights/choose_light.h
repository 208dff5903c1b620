/* choose_light.h — next-event estimation over every light in the scene: one
 * entry of the alias table, chosen by power (host/device/device_scene.cpp), then a
 * sample of that light by its kind. The returned pdf includes the choice. */
#ifndef WF_CHOOSE_LIGHT_H
#define WF_CHOOSE_LIGHT_H

#include "wavefront/compat.h"
#include "wavefront/render_params.h"
#include "compiled_features.h"
#include "scene_view.h"
#include "lights/light_sample.h"
#include "lights/emissive_triangles.h"
#include "lights/environment.h"
#include "lights/punctual.h"

WF_INLINE uint choose_light(__global const LightEntry* lights, uint count, float u_index, float u_alias) {
    const uint i = min((uint)(u_index * (float)count), count - 1u);
    return u_alias < lights[i].probability ? i : lights[i].alias;
}

/* u.x and u.w choose the light; u.y and u.z place the sample on it. */
WF_INLINE LightSample sample_light(const RenderParams* params, const Scene* scene, float3 receiver, float4 u) {
    const LightEntry entry = scene->lights[choose_light(scene->lights, params->light_count, u.x, u.w)];
#if WF_HAS_EMISSIVE_TRIANGLES
    if (entry.kind == WF_LIGHT_TRIANGLE)
        return sample_emissive_triangle(entry, scene, receiver, u.yz);
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
