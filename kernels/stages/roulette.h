/* roulette — ends paths whose throughput has become small, without bias.
 *
 * From params.roulette_depth bounces on, a path survives with probability
 * q = min(roulette_cap, max component of its throughput) and its throughput is
 * divided by q; survivors return to the extension queue, the rest are
 * finished. A cap below 1 (Mitsuba's 0.95) also ends paths that lose nothing,
 * such as light trapped in glass by total internal reflection. */
#ifndef WF_STAGE_ROULETTE_H
#define WF_STAGE_ROULETTE_H

#include "wavefront/compat.h"
#include "wavefront/stage_graph.h"
#include "path_view.h"
#include "stages/stage_step.h"

/* Returns the queue the path goes to next: extension if it survives. */
WF_INLINE uint roulette_path(PathState* path, const RenderParams* params, uint slot) {
    const uint depth = path_depth(path, slot);
    if (depth < params->roulette_depth) return WF_QUEUE_EXTEND;
    const float3 throughput = path->throughput[slot].xyz;
    const float q = min(params->roulette_cap, max(throughput.x, max(throughput.y, throughput.z)));
    /* The fourth number of the BSDF group of the bounce that chose this ray,
     * which shade handed on with it; bsdf_sample uses the first three, so the
     * choice to go on is independent of the direction (and of the throughput
     * that direction gave). */
    if (!(path_roulette_number(path, slot) < q)) return WF_QUEUE_FINISHED;
    set_path_throughput(path, slot, throughput / q, depth);
    return WF_QUEUE_EXTEND;
}

WF_FORCE_INLINE uint roulette_step(const StageView* v, uint slot, StageTally* t) {
    (void)t;
    return roulette_path(v->path, v->params, slot);
}

#endif
