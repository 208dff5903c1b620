// run_render.h — a render session from start to end, whoever asks for it
// (the command line, rank 0 of an MPI render, the Python module): load and
// check everything, render in rounds with a checkpoint table and a progress
// line, denoise, write the image and return the summary.
#pragma once

#include <atomic>
#include <iosfwd>

#include "render/render_report.h"
#include "session/render_hooks.h"
#include "session/render_options.h"

namespace wf {

// Runs one render as the options say: checkpoints as a table on `out` (and in
// the CSV file), notes on `log`, the image written, and the summary returned.
RenderSummary run_render(const RenderOptions& options, std::ostream& out, std::ostream& log,
                         const RenderHooks& hooks = {});

// The options' render settings with the cache directory resolved and `stop`
// as the stop flag.
RenderSettings device_settings(const RenderOptions& options, const std::atomic<int>* stop);

} // namespace wf
