/* stage_step.h — what every stage's step takes, so that the megakernel
 * (kernels/megakernel.cl) walks a path through the stage list
 * (wavefront/stage_graph.h) without naming a stage: each stage file gives
 * `<kernel>_step(view, slot, tally)`, which moves one path from the queue the
 * stage consumes and returns the queue it goes to next. */
#ifndef WF_STAGE_STEP_H
#define WF_STAGE_STEP_H

#include "wavefront/compat.h"
#include "wavefront/stage_graph.h"
#include "path_view.h"
#include "scene_view.h"
#include "film_view.h"

/* The kernel's views of its arguments. */
typedef struct StageView {
    PathState* path;
    const RenderParams* params;
    const Camera* camera;
    const Scene* scene;
    const FilmBuffers* film;
} StageView;

/* What a work-item's steps counted, for the render's counters. */
typedef struct StageTally {
    uint started;      /* camera samples */
    uint closest_rays;
    uint shadow_rays;
    uint nonfinite;    /* finished samples dropped as non-finite */
} StageTally;

#endif
