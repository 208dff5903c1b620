// render_hooks.h — what a caller other than the command line adds to a
// render (run_render.h): rank 0 of an MPI render (host/cluster/) its other
// ranks' devices, the Python module (host/python/) a scene and reference in
// memory, its own stop flag, callbacks, and the film and denoised image back.
#pragma once

#include <atomic>
#include <functional>

#include "render/progressive_render.h"
#include "render/renderer.h"

namespace wf {

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

} // namespace wf
