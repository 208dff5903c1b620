/* punctual.h — glTF KHR_lights_punctual lights (point, spot, directional),
 * shared by the kernels and the host. They are delta lights: a receiver sees
 * each from exactly one direction, so they are reached only by next-event
 * estimation, never by BRDF sampling, and take no MIS weight. Their sample
 * carries Li, the irradiance at normal incidence (W/m^2): the estimator adds
 * f * Li * |cos theta| with no division by a pdf.
 *
 * Units: glTF's candela and lux are read as W/sr and W/m^2 with the same
 * number. Point and spot: Li = I * spot(cd) / r^2. Spot falloff as glTF's
 * spec gives it: t = clamp((cd - cos_outer) / max(1e-3, cos_inner -
 * cos_outer), 0, 1), spot = t^2, where cd is the cosine between the spot's
 * axis and the direction from the light to the receiver. Directional: Li = E,
 * at distance INFINITY. glTF's range is not applied (the spec allows a
 * renderer to ignore it; applying it would break 1/r^2). */
#ifndef WF_PUNCTUAL_H
#define WF_PUNCTUAL_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"

WF_DEVICE_BEGIN

typedef struct PunctualSample {
    float3 direction; /* unit, from the receiver toward the light */
    float distance;   /* to the light; INFINITY when directional */
    float3 Li;        /* irradiance at normal incidence, W/m^2; zero outside a spot's cone */
} PunctualSample;

/* glTF's smooth cone falloff, 1 inside the inner cone, 0 outside the outer. */
WF_INLINE float punctual_spot_falloff(PunctualLight light, float cos_angle) {
    const float t = clamp((cos_angle - light.cos_outer) / max(1e-3f, light.cos_inner - light.cos_outer), 0.0f, 1.0f);
    return t * t;
}

WF_INLINE PunctualSample punctual_sample(PunctualLight light, float3 receiver) {
    PunctualSample s;
    const float3 axis = make_float3(light.direction[0], light.direction[1], light.direction[2]);
    const float3 intensity = make_float3(light.intensity[0], light.intensity[1], light.intensity[2]);
    if (light.type == WF_PUNCTUAL_DIRECTIONAL) {
        s.direction = -axis;
        s.distance = INFINITY;
        s.Li = intensity;
        return s;
    }
    const float3 to_light = make_float3(light.position[0], light.position[1], light.position[2]) - receiver;
    const float dist2 = dot(to_light, to_light);
    s.distance = sqrt(dist2);
    s.direction = to_light / s.distance;
    const float falloff = light.type == WF_PUNCTUAL_SPOT ? punctual_spot_falloff(light, -dot(s.direction, axis)) : 1.0f;
    s.Li = dist2 > 0.0f ? intensity * (falloff / dist2) : make_float3(0.0f, 0.0f, 0.0f);
    return s;
}

WF_DEVICE_END

#endif
