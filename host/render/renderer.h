// renderer.h — a render over one or several OpenCL devices, with the same
// bytes either way. With one device it traces the whole image every round
// (device_renderer.h). With several, each device runs in a host thread of its
// own and pulls units of work (work_units.h): runs of pixels whose sums travel
// through the image the host keeps, so that each pixel is traced by one device
// at a time, in its sample order. The command line and the tests both go
// through it; progressive_render.h calls it round by round.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <vector>

#include "render/device_renderer.h"

namespace wf {

class Renderer {
public:
    // Throws InputError when the render cannot fit a device, before allocating.
    Renderer(const OpenClDevice& device, const Scene& scene, const SceneCamera& camera, ImageSize size,
             const RenderSettings& settings);
    Renderer(const std::vector<const OpenClDevice*>& devices, const Scene& scene, const SceneCamera& camera,
             ImageSize size, const RenderSettings& settings);

    // Continues every pixel up to `spp` samples, unless settings.stop ends the round early.
    void render_to(uint32_t spp);
    // Goes on from a stopped render's film (host/film/partial_render.h), which
    // must have this image's size; returns the fewest samples a pixel has.
    // Throws InputError otherwise.
    uint32_t resume(const FilmState& state);
    // Called after every read of a device's counters, with what every device has done.
    void on_progress(std::function<void(const RenderStats&)> f);
    FilmReadout read() const;
    FilmState film_state() const;
    // Every device's statistics together; the time is the render's wall time.
    RenderStats stats() const;

    // What the closing report says of this render so far.
    RenderSummary summary() const;

private:
    // Units of work over the devices, each in a thread of its own when there are several.
    void render_units(uint32_t spp);

    std::vector<std::unique_ptr<DeviceRenderer>> devices_;
    uint32_t pixels_ = 0;
    // By units of work: the image as the devices last left it, and per pixel
    // the device whose film holds the same sums (kEveryDevice, kNoDevice).
    bool by_units_ = false;
    FilmState image_;
    std::vector<int> holder_;
    static constexpr int kEveryDevice = -1, kNoDevice = -2;
    const std::atomic<int>* stop_;
    // Guarded by progress_mutex_ while the devices' threads run:
    mutable std::mutex progress_mutex_;
    std::vector<DeviceShare> shares_; // units and times; the samples from each device's stats
    std::vector<RenderStats> latest_; // each device's counts at its last progress report
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
