/* light_sample.h — what next-event estimation gets from any light, and how its
 * shadow ray ends. The kinds (include/wavefront/scene_types.h) sample
 * themselves in lights/light_lanes.inc, lights/punctual.h and
 * lights/environment.h; lights/choose_light.h picks one of them. The shadow
 * segment is the scatter's (stages/scatter.inc). */
#ifndef WF_LIGHT_SAMPLE_H
#define WF_LIGHT_SAMPLE_H

#include "wavefront/compat.h"

#define WF_SEGMENT_TO_SURFACE 0u  /* stops short of the light's surface: area lights */
#define WF_SEGMENT_TO_POINT 1u    /* ends at the light: point and spot lights */
#define WF_SEGMENT_TO_INFINITY 2u /* leaves the scene: the environment, directional lights */

typedef struct LightSample {
    float3 wi;          /* unit, from the receiver toward the light */
    float3 radiance;    /* arriving along -wi; for a delta light Li, the irradiance at normal incidence */
    float pdf;          /* solid angle, the light's choice included; for a delta light the choice alone;
                           0 when unusable */
    bool delta;         /* a delta light: no MIS weight, and no BRDF sample will ever find it */
    uint segment_end;   /* WF_SEGMENT_* */
    float3 point;       /* area lights: the sampled point; point and spot lights: their position */
    float3 point_error; /* area lights: per component, as geometry/ray_offset.h bounds it */
    float3 normal;      /* area lights: unit, of the emitting face toward the receiver */
} LightSample;

WF_INLINE LightSample no_light_sample(void) {
    LightSample s;
    s.wi = s.radiance = s.point = s.point_error = s.normal = (float3)(0.0f);
    s.pdf = 0.0f;
    s.delta = false;
    s.segment_end = WF_SEGMENT_TO_INFINITY;
    return s;
}

#endif
