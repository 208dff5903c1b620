// render_command.h — `wavefront render`, `wavefront devices` and
// `wavefront cache`: what app/main.cpp runs for each command.
#pragma once

#include <atomic>
#include <functional>
#include <iosfwd>

#include "cli/cli.h"
#include "render/progressive_render.h"
#include "render/render_report.h"
#include "render/renderer.h"

namespace wf {

// What a caller other than the command line adds to a render: rank 0 of an
// MPI render (host/cluster/), the Python module (host/python/).
struct RenderHooks {
    // The scene, loaded already from options.scene (with options.camera); a
    // copy of it is lit as the options say.
    const Scene* scene = nullptr;
    // The reference, given as an image rather than as options.reference.
    const Image* reference = nullptr;
    // Called once the renderer is ready, before it resumes or renders.
    std::function<void(Renderer&, ImageSize)> add_workers;
    // Set (to a signal's number) to stop the render as Ctrl-C does; without
    // it, Ctrl-C and SIGTERM stop it through signal handlers.
    const std::atomic<int>* stop = nullptr;
    // As the render goes: the statistics at every read of the counters, and each checkpoint.
    std::function<void(const RenderStats&)> on_progress;
    std::function<void(const Checkpoint&)> on_checkpoint;
    // Receives the final film. With `write_image` false, neither the image
    // nor a partial render is written (nor checked beforehand).
    FilmReadout* film = nullptr;
    bool write_image = true;
    // With options.denoise, receives the denoised image (film->mean stays the noisy one).
    Image* denoised = nullptr;
};

// Runs one render as the options say: checkpoints as a table on `out` (and in
// the CSV file), notes on `log`, the image written, and the summary returned.
RenderSummary run_render(const RenderOptions& options, std::ostream& out, std::ostream& log,
                         const RenderHooks& hooks = {});

// The scene the options name, with its environment and a light if it has
// none (light_for_render): what every rank of a render loads. Warnings go to `log`.
Scene load_render_scene(const RenderOptions& options, std::ostream& log);
void light_for_render(Scene& scene, const RenderOptions& options, std::ostream& log);

// The options' render settings with the cache directory resolved and `stop`
// as the stop flag.
RenderSettings device_settings(const RenderOptions& options, const std::atomic<int>* stop);

// `wavefront devices`: every OpenCL device with its index.
void print_devices(std::ostream& out);

// The program cache's directory: `requested`, else the default; empty with neither.
std::string cache_directory(const std::string& requested);

// `wavefront cache warm`: compiles the kernels each scene needs into the cache.
void warm_cache(const CacheOptions& options, std::ostream& out);

// `wavefront cache clear`.
void clear_cache(const CacheOptions& options, std::ostream& out);

} // namespace wf
