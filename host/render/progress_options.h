// progress_options.h — when a progressive render (progressive_render.h)
// stops and how often it reports: a time budget, a target error, Ctrl-C, and
// the sample count the settings ask for (RenderSettings::spp, not copied
// here). No OpenCL: the command line fills it in.
#pragma once

#include <atomic>
#include <cstdint>

#include "image/image.h"

namespace wf {

struct ProgressOptions {
    double time_budget = 0.0;   // seconds; 0: none
    double target_relmse = 0.0; // stop once the estimated relMSE falls below it (from 16 spp on); 0: none
    // Pixels stop apart, each when its samples are what its variance is
    // worth toward target_relmse (render/adaptive_sampling.h); needs the
    // target, and one device rendering in place.
    bool adaptive = false;
    double report_every = 0.0;  // seconds between checkpoints; 0: at each doubling of spp
    const Image* reference = nullptr;
    uint32_t start_spp = 0; // the samples every pixel already has (a resumed render)
    // Set by Ctrl-C (RenderSettings::stop): the round in flight ends early and is the last.
    const std::atomic<int>* stop = nullptr;
};

} // namespace wf
