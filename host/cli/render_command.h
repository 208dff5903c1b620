// render_command.h — `wavefront render`, `wavefront devices` and
// `wavefront cache`: what main.cpp runs for each command.
#pragma once

#include <iosfwd>

#include "cli/cli.h"
#include "render/render_report.h"

namespace wf {

// Runs one render as the options say: checkpoints as a table on `out` (and in
// the CSV file), notes on `log`, the image written, and the summary returned.
RenderSummary run_render(const RenderOptions& options, std::ostream& out, std::ostream& log);

// `wavefront devices`: every OpenCL device with its index.
void print_devices(std::ostream& out);

// The program cache's directory: `requested`, else the default; empty with neither.
std::string cache_directory(const std::string& requested);

// `wavefront cache warm`: compiles the kernels each scene needs into the cache.
void warm_cache(const CacheOptions& options, std::ostream& out);

// `wavefront cache clear`.
void clear_cache(const CacheOptions& options, std::ostream& out);

} // namespace wf
