// render_command.h — `wavefront render`, `wavefront devices` and
// `wavefront cache`: what app/main.cpp runs for each command.
#pragma once

#include <functional>
#include <iosfwd>

#include "cli/cli.h"
#include "render/render_report.h"
#include "render/renderer.h"

namespace wf {

// Runs one render as the options say: checkpoints as a table on `out` (and in
// the CSV file), notes on `log`, the image written, and the summary returned.
// `add_workers`, if given, is called once the renderer is ready and before it
// resumes or renders (rank 0 adds the other ranks' devices there).
RenderSummary run_render(const RenderOptions& options, std::ostream& out, std::ostream& log,
                         const std::function<void(Renderer&, ImageSize)>& add_workers = {});

// The scene the options name, with its environment and a light if it has
// none: what every rank of a render loads. Warnings go to `log`.
Scene load_render_scene(const RenderOptions& options, std::ostream& log);

// The options' render settings with the cache directory resolved and the
// interrupt handlers' flag as the stop flag.
RenderSettings device_settings(const RenderOptions& options);

// `wavefront devices`: every OpenCL device with its index.
void print_devices(std::ostream& out);

// The program cache's directory: `requested`, else the default; empty with neither.
std::string cache_directory(const std::string& requested);

// `wavefront cache warm`: compiles the kernels each scene needs into the cache.
void warm_cache(const CacheOptions& options, std::ostream& out);

// `wavefront cache clear`.
void clear_cache(const CacheOptions& options, std::ostream& out);

} // namespace wf
