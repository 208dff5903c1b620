// renderer.h — a scene made ready on one device: its BVH built and uploaded,
// the memory it needs checked against the device, the kernels built and the
// integrator (wavefront or megakernel) set up. It then renders in rounds, and its film can be
// read between them. The command line and the tests both go through it.
#pragma once

#include <memory>

#include "scene/camera.h"
#include "device/device_scene.h"
#include "film/film.h"
#include "device/kernel_program.h"
#include "device/opencl_device.h"
#include "render/render_report.h"
#include "scene/scene.h"
#include "integrator/path_integrator.h"

namespace wf {

// The stage kernels for `scene`: compiled for its features unless
// settings.specialize is off, through the program cache in settings.cache_dir
// if one is set. `features_described`, if given, receives what was compiled in.
KernelProgram build_render_program(const OpenClDevice& device, const Scene& scene, const RenderSettings& settings,
                                   std::string* features_described = nullptr);

class Renderer {
public:
    // Throws InputError when the render cannot fit the device, before allocating.
    Renderer(const OpenClDevice& device, const Scene& scene, const SceneCamera& camera, ImageSize size,
             const RenderSettings& settings);

    // Continues every pixel up to `spp` samples, unless settings.stop ends the round early.
    void render_to(uint32_t spp) { scheduler_->render_to(spp); }
    // Goes on from a stopped render's film (host/film/partial_render.h), which must
    // have this image's size and the sample counts this pool size leaves;
    // returns the fewest samples a pixel has. Throws InputError otherwise.
    uint32_t resume(const FilmState& state);
    void on_progress(std::function<void(const RenderStats&)> f) { scheduler_->on_progress(std::move(f)); }
    FilmReadout read() const { return scheduler_->film().read(device_.queue); }
    FilmState film_state() const { return scheduler_->film().state(device_.queue); }
    const RenderStats& stats() const { return scheduler_->stats(); }

    // What the closing report says of this render so far.
    RenderSummary summary() const;

private:
    const OpenClDevice& device_;
    RenderSummary summary_;
    DeviceScene device_scene_;
    KernelProgram program_;
    std::unique_ptr<PathIntegrator> scheduler_;
};

struct RenderOutput {
    FilmReadout film;
    RenderSummary summary;
};

// Renders `settings.spp` samples per pixel in one round: what the tests use.
RenderOutput render_scene(const OpenClDevice& device, const Scene& scene, const SceneCamera& camera,
                          ImageSize size, const RenderSettings& settings);

} // namespace wf
