// progressive_render.h — rendering in rounds with a checkpoint after each:
// how long it has run, how many samples per pixel it has, and how wrong the
// image still is (against a reference if given, and always estimated from the
// render's own variance). It stops at the sample count, the time budget or
// the target error, whichever comes first, or when `stop` is set. With
// adaptive sampling, pixels stop one by one and the rounds go on with the rest.
#pragma once

#include <functional>
#include <optional>

#include "image/error_metrics.h"
#include "render/progress_options.h"
#include "render/renderer.h"

namespace wf {

struct Checkpoint {
    double seconds = 0.0; // wall time since the first round started, readbacks included
    uint32_t spp = 0;                      // the most a pixel has: every pixel's but adaptive sampling's
    uint32_t pixels_sampling = 0;          // pixels the next round continues (all but those adaptive sampling stopped)
    std::optional<ErrorMetrics> error;     // against the reference, when there is one
    std::optional<double> relmse_estimate; // from 2 spp on: one sample has no variance
};

// Renders up to `spp` samples per pixel (RenderSettings::spp; 0: no limit, a
// time budget or target error ends the render) or until another stop
// condition holds, calling `on_checkpoint` after every round. Returns the
// final film. Throws InputError when adaptive sampling is asked of a render
// that does not run in place (Renderer::renders_in_place).
FilmReadout render_progressively(Renderer& renderer, uint32_t spp, const ProgressOptions& options,
                                 const std::function<void(const Checkpoint&)>& on_checkpoint);

} // namespace wf
