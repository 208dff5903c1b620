// device_renderer.h — a scene made ready on one device: uploaded, the memory
// it needs checked against the device, the kernels built and the integrator
// (wavefront or megakernel) set up. A Renderer (renderer.h) drives one per
// device: over the whole image when it has one device, or unit by unit, each a
// run of pixels, when it has several.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "bvh/bvh_builder.h"
#include "device/device_scene.h"
#include "device/kernel_program.h"
#include "device/opencl_device.h"
#include "device/scene_features.h"
#include "film/film.h"
#include "integrator/path_integrator.h"
#include "render/render_report.h"
#include "render/unit_worker.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace wf {

// What build_render_program compiles for a device of this kind: the root
// source under kernels/ and the build options. bench/gpu_isa.py compiles the
// same for GPU instruction sets through bench/kernel_source.cpp.
struct RenderProgramSource {
    std::string root;
    std::string options;
};
RenderProgramSource render_program_source(const DeviceInfo& device, const SceneFeatures& features,
                                          const RenderSettings& settings);

// The stage kernels for `scene`: compiled for its features unless
// settings.specialize is off, through the program cache in settings.cache_dir
// if one is set. `features_described`, if given, receives what was compiled in.
KernelProgram build_render_program(const OpenClDevice& device, const Scene& scene, const RenderSettings& settings,
                                   std::string* features_described = nullptr);

// Kernels for a GPU, or for a CPU: as asked, else the device's kind.
bool gpu_kernels(const DeviceInfo& device, const RenderSettings& settings);

// The scene the devices render: `scene`, or where one of them gets a GPU's
// kernels, whose traversal walks one tree (kernels/geometry/bvh_traverse.h),
// `scene` with its instances written out in world space, kept in `flat`.
// Every device renders the same, so that they make the same bytes.
const Scene& scene_for_devices(const Scene& scene, const std::vector<const OpenClDevice*>& devices,
                               const RenderSettings& settings, std::optional<Scene>& flat);

// What is built once on the host for every device: the BVH and the buffers' contents.
struct SceneBuild {
    SceneBuild(const Scene& scene);
    Bvh bvh;
    DeviceSceneData data;
    double seconds = 0.0; // building the BVH
};

class DeviceRenderer : public UnitWorker {
public:
    // Throws InputError when the render cannot fit the device, before allocating.
    DeviceRenderer(const OpenClDevice& device, const Scene& scene, const SceneBuild& build, const SceneCamera& camera,
                   ImageSize size, const RenderSettings& settings);

    // A round: continues every pixel it traces up to `round_spp` samples, unless settings.stop ends it early.
    void render_to(uint32_t round_spp) { integrator_->render_to(round_spp); }
    // A round of adaptive sampling: continues the listed pixels, each of which has `from` samples, up to `round_spp`.
    void render_pixels_to(const std::vector<uint32_t>& pixels, uint32_t from, uint32_t round_spp) {
        integrator_->trace_pixel_list(pixels, from);
        integrator_->render_to(round_spp);
    }
    // Goes on from a stopped render's film (host/film/partial_render.h) over
    // the whole image, when its sample counts are those this pool leaves;
    // false, and nothing changed, when they are not.
    bool resume(const FilmState& state);
    // A unit of work (unit_worker.h), one path slot a pixel.
    void render_unit(uint32_t first, uint32_t count, uint32_t round_spp, FilmState& image, bool held) override;
    std::string name() const override { return device_.info.name; }
    uint32_t most_pixels() const override { return stats().pool_size; }
    RenderStats counts() const override { return stats().without_counter_reads(); }
    double transfer_seconds() const override { return transfer_seconds_; }

    void on_progress(std::function<void(const RenderStats&)> f) { integrator_->on_progress(std::move(f)); }
    FilmReadout read() const { return integrator_->film().read(device_.queue); }
    FilmState film_state() const { return integrator_->film().state(device_.queue); }
    const RenderStats& stats() const { return integrator_->stats(); }

    // What the closing report says of this device's render so far.
    RenderSummary summary() const;

private:
    const OpenClDevice& device_;
    RenderSummary summary_;
    DeviceScene device_scene_;
    KernelProgram program_;
    std::unique_ptr<PathIntegrator> integrator_;
    double transfer_seconds_ = 0.0;
};

} // namespace wf
