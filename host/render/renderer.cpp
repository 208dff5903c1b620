// renderer.cpp — one device renders the whole image in place; several share
// rounds in units of work. A unit's sums are written to its device only when
// that device's film does not hold them already, and read back after it, so
// the host's image is always current and a device may stop at any unit.
#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <thread>

#include "base/errors.h"
#include "render/work_units.h"

namespace wf {
namespace {

double since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

Renderer::Renderer(const OpenClDevice& device, const Scene& scene, const SceneCamera& camera, ImageSize size,
                   const RenderSettings& settings)
    : Renderer(std::vector<const OpenClDevice*>{&device}, scene, camera, size, settings) {}

Renderer::Renderer(const std::vector<const OpenClDevice*>& devices, const Scene& scene, const SceneCamera& camera,
                   ImageSize size, const RenderSettings& settings)
    : pixels_(size.width * size.height), stop_(settings.stop) {
    const SceneBuild build(scene);
    for (const OpenClDevice* device : devices)
        devices_.push_back(std::make_unique<DeviceRenderer>(*device, scene, build, camera, size, settings));
    shares_.resize(devices_.size());
    for (size_t d = 0; d < devices_.size(); ++d) shares_[d].device = devices_[d]->device().info.name;
    by_units_ = devices_.size() > 1;
    if (by_units_) {
        image_ = devices_[0]->film_state(); // zeroes, as every device's film is
        holder_.assign(pixels_, kEveryDevice);
    }
}

void Renderer::render_to(uint32_t spp) {
    if (!by_units_) return devices_[0]->render_to(spp);
    round_start_ = std::chrono::steady_clock::now();
    in_round_ = true;
    render_units(spp);
    std::lock_guard<std::mutex> lock(progress_mutex_);
    in_round_ = false;
    seconds_ += since(round_start_);
}

void Renderer::render_units(uint32_t spp) {
    WorkUnits units(pixels_, static_cast<uint32_t>(devices_.size()));
    std::atomic<bool> failed{false};
    std::vector<std::exception_ptr> errors(devices_.size());
    auto work = [&](size_t d) {
        DeviceRenderer& device = *devices_[d];
        try {
            for (;;) {
                const PixelRun run = units.next(device.stats().pool_size);
                if (run.count == 0 || failed) return;
                const auto start = std::chrono::steady_clock::now();
                const bool held = std::all_of(holder_.begin() + run.first, holder_.begin() + run.first + run.count,
                                              [&](int h) { return h == static_cast<int>(d) || h == kEveryDevice; });
                device.render_unit(run.first, run.count, spp, image_, held);
                std::fill_n(holder_.begin() + run.first, run.count, static_cast<int>(d));
                std::lock_guard<std::mutex> lock(progress_mutex_);
                shares_[d].units += 1;
                shares_[d].busy_seconds += since(start);
                shares_[d].transfer_seconds = device.transfer_seconds();
                if (stop_ && stop_->load() != 0) return; // its integrator stopped too, within the unit
            }
        } catch (...) {
            errors[d] = std::current_exception();
            failed = true;
        }
    };
    if (devices_.size() == 1) {
        work(0);
    } else {
        std::vector<std::thread> threads;
        for (size_t d = 0; d < devices_.size(); ++d) threads.emplace_back(work, d);
        for (std::thread& t : threads) t.join();
    }
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

uint32_t Renderer::resume(const FilmState& state) {
    const uint32_t width = devices_[0]->summary().width, height = devices_[0]->summary().height;
    if (state.width != width || state.height != height)
        throw InputError("the partial render is " + std::to_string(state.width) + "x" + std::to_string(state.height) +
                         ", not " + std::to_string(width) + "x" + std::to_string(height));
    // One device goes on in place from counts its own pool left; any other
    // counts, and several devices, go on by units, which take each pixel from
    // wherever it stopped.
    if (by_units_ || !devices_[0]->resume(state)) {
        by_units_ = true;
        image_ = state;
        image_.bounce_layers = 0; // a partial render keeps none
        holder_.assign(pixels_, kNoDevice);
    }
    return state.samples.empty() ? 0 : *std::min_element(state.samples.begin(), state.samples.end());
}

void Renderer::on_progress(std::function<void(const RenderStats&)> f) {
    if (devices_.size() == 1) return devices_[0]->on_progress(std::move(f));
    // Each device reports from its own thread: its counts are copied under
    // the lock, and the sum of every device's last counts is passed on.
    latest_.assign(devices_.size(), RenderStats{});
    for (size_t d = 0; d < devices_.size(); ++d)
        devices_[d]->on_progress([this, f, d](const RenderStats& s) {
            std::lock_guard<std::mutex> lock(progress_mutex_);
            latest_[d] = RenderStats{};
            latest_[d].add(s, false);
            RenderStats total;
            for (const RenderStats& part : latest_) total.add(part, false);
            total.seconds = seconds_ + (in_round_ ? since(round_start_) : 0.0);
            f(total);
        });
}

FilmReadout Renderer::read() const { return by_units_ ? resolve(image_) : devices_[0]->read(); }

FilmState Renderer::film_state() const { return by_units_ ? image_ : devices_[0]->film_state(); }

RenderStats Renderer::stats() const {
    if (!by_units_) return devices_[0]->stats();
    RenderStats total = devices_[0]->stats();
    for (size_t d = 1; d < devices_.size(); ++d) total.add(devices_[d]->stats(), true);
    std::lock_guard<std::mutex> lock(progress_mutex_);
    total.seconds = seconds_;
    return total;
}

RenderSummary Renderer::summary() const {
    RenderSummary s = devices_[0]->summary();
    if (devices_.size() == 1) return s;
    s.stats = stats();
    s.spp = static_cast<uint32_t>(s.stats.samples / pixels_);
    s.device = std::to_string(devices_.size()) + " devices";
    s.shares = shares_;
    for (size_t d = 0; d < devices_.size(); ++d) {
        const RenderSummary part = devices_[d]->summary();
        if (d > 0) s.device_bytes += part.device_bytes, s.times.kernel_build += part.times.kernel_build;
        s.kernels_from_cache = s.kernels_from_cache && part.kernels_from_cache;
        s.shares[d].samples = part.stats.samples;
    }
    return s;
}

RenderOutput render_scene(const OpenClDevice& device, const Scene& scene, const SceneCamera& camera,
                          ImageSize size, const RenderSettings& settings) {
    Renderer renderer(device, scene, camera, size, settings);
    renderer.render_to(settings.spp);
    return RenderOutput{renderer.read(), renderer.summary()};
}

} // namespace wf
