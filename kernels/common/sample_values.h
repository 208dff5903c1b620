/* sample_values.h — the four sample values a stage draws for one (pixel,
 * sample, bounce, dimension group), from the sampler the render chose. Both
 * samplers are pure functions of their key, so either keeps the image
 * independent of the schedule. */
#ifndef WF_SAMPLE_VALUES_H
#define WF_SAMPLE_VALUES_H

#include "wavefront/compat.h"
#include "wavefront/render_params.h"
#include "common/rng.h"
#include "common/sobol.h"

WF_INLINE float4 sample_values(const RenderParams* params, uint pixel, uint sample, uint bounce, uint group) {
    return params->sampler == WF_SAMPLER_SOBOL ? sobol_uniform4(params->seed, pixel, sample, bounce, group)
                                               : rng_uniform4(params->seed, pixel, sample, bounce, group);
}

#endif
