// progressive_render.h — rendering in rounds with a checkpoint after each:
// how long it has run, how many samples per pixel it has, and how wrong the
// image still is (against a reference if given, and always estimated from the
// render's own variance). It stops at the sample count, the time budget or
// the target error, whichever comes first, or when `stop` is set.
#pragma once

#include <atomic>
#include <functional>
#include <optional>

#include "image/error_metrics.h"
#include "render/renderer.h"

namespace wf {

struct ProgressOptions {
    uint32_t max_spp = 16;      // 0: no limit (a time budget or target error ends the render)
    double time_budget = 0.0;   // seconds; 0: none
    double target_relmse = 0.0; // stop once the estimated relMSE falls below it (from 16 spp on); 0: none
    double report_every = 0.0;  // seconds between checkpoints; 0: at each doubling of spp
    const Image* reference = nullptr;
    uint32_t start_spp = 0; // the samples every pixel already has (a resumed render)
    // Set by Ctrl-C (RenderSettings::stop): the round in flight ends early and is the last.
    const std::atomic<int>* stop = nullptr;
};

struct Checkpoint {
    double seconds = 0.0; // wall time since the first round started, readbacks included
    uint32_t spp = 0;
    std::optional<ErrorMetrics> error;     // against the reference, when there is one
    std::optional<double> relmse_estimate; // from 2 spp on: one sample has no variance
};

// Renders until a stop condition holds, calling `on_checkpoint` after every
// round. Returns the final film.
FilmReadout render_progressively(Renderer& renderer, const ProgressOptions& options,
                                 const std::function<void(const Checkpoint&)>& on_checkpoint);

} // namespace wf
