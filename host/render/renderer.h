// renderer.h — a render over one or several OpenCL devices, with the same
// bytes either way. With one device it traces the whole image every round
// (device_renderer.h). With several, each device runs in a host thread of its
// own and pulls units of work (work_units.h): runs of pixels whose sums travel
// through the image the host keeps, so that each pixel is traced by one device
// at a time, in its sample order. Devices of other MPI ranks join as workers
// like any other (host/cluster/). The command line and the tests both go
// through it; progressive_render.h calls it round by round.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <vector>

#include "render/device_renderer.h"
#include "render/unit_worker.h"

namespace wf {

class Renderer {
public:
    // Throws InputError when the render cannot fit a device, before allocating.
    Renderer(const OpenClDevice& device, const Scene& scene, const SceneCamera& camera, ImageSize size,
             const RenderSettings& settings);
    Renderer(const std::vector<const OpenClDevice*>& devices, const Scene& scene, const SceneCamera& camera,
             ImageSize size, const RenderSettings& settings);

    // Workers beyond this process's devices (another rank's), before resume()
    // and the first round: from then on every round goes by units.
    void add_workers(std::vector<std::unique_ptr<UnitWorker>> workers);

    // A round: continues every pixel up to `round_spp` samples, unless settings.stop ends it early.
    void render_to(uint32_t round_spp);
    // A round of adaptive sampling (adaptive_sampling.h): continues the listed
    // pixels, each of which has `from` samples, up to `round_spp`. Only where
    // one device renders the image in place (renders_in_place()).
    void render_pixels_to(const std::vector<uint32_t>& pixels, uint32_t from, uint32_t round_spp);
    // One device, the whole image on it: not units of work over several
    // devices, nor a partial render its pool did not leave.
    bool renders_in_place() const { return !by_units_; }
    // Goes on from a stopped render's film (host/film/partial_render.h), which
    // must have this image's size; returns the fewest samples a pixel has.
    // Throws InputError otherwise.
    uint32_t resume(const FilmState& state);
    // Called as work is done: after every read of a device's counters, and
    // after each unit of another rank's; with what every worker has done.
    void on_progress(std::function<void(const RenderStats&)> f);
    FilmReadout read() const;
    ImageSize size() const { return size_; }
    FilmState film_state() const;
    // Every worker's statistics together; the time is the render's wall time.
    RenderStats stats() const;

    // What the closing report says of this render so far.
    RenderSummary summary() const;

private:
    // Units of work over the workers, each in a thread of its own when there are several.
    void render_units(uint32_t round_spp);
    // Under progress_mutex_: worker w's counts as they now are, passed on summed.
    void report_progress(size_t w, const RenderStats& counts);

    std::vector<std::unique_ptr<DeviceRenderer>> devices_; // this process's
    std::vector<std::unique_ptr<UnitWorker>> remote_;      // other ranks' devices
    std::vector<UnitWorker*> workers_;                     // devices_, then remote_
    ImageSize size_;
    uint32_t pixels() const { return size_.width * size_.height; }
    // By units of work: the image as the workers last left it, and per pixel
    // the worker whose film holds the same sums (kEveryWorker, kNoWorker).
    bool by_units_ = false;
    FilmState image_;
    std::vector<int> holder_;
    static constexpr int kEveryWorker = -1, kNoWorker = -2;
    const std::atomic<int>* stop_;
    // Guarded by progress_mutex_ while the workers' threads run:
    mutable std::mutex progress_mutex_;
    std::function<void(const RenderStats&)> progress_;
    std::vector<DeviceShare> shares_; // units and times; the samples from each worker's counts
    std::vector<RenderStats> latest_; // each worker's counts at its last progress report
    double seconds_ = 0.0;            // wall time in render_to() while rendering by units
    bool in_round_ = false;
    std::chrono::steady_clock::time_point round_start_;
};

struct RenderOutput {
    FilmReadout film;
    RenderSummary summary;
};

// Renders `settings.spp` samples per pixel in one round: what the tests use.
RenderOutput render_scene(const OpenClDevice& device, const Scene& scene, const SceneCamera& camera,
                          ImageSize size, const RenderSettings& settings);

} // namespace wf
