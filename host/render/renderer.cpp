// renderer.cpp — one device renders the whole image in place; several
// workers share rounds in units of work. A unit's sums go to its worker only
// when the worker's film does not hold them already, and come back after it,
// so the host's image is always current and a worker may stop at any unit.
#include "render/renderer.h"

#include <algorithm>
#include <exception>
#include <stdexcept>
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
    : size_(size), stop_(settings.stop) {
    std::optional<Scene> flat;
    const Scene& rendered = scene_for_devices(scene, devices, settings, flat);
    const SceneBuild build(rendered);
    for (const OpenClDevice* device : devices)
        devices_.push_back(std::make_unique<DeviceRenderer>(*device, rendered, build, camera, size, settings));
    add_workers({});
}

void Renderer::add_workers(std::vector<std::unique_ptr<UnitWorker>> workers) {
    for (auto& w : workers) remote_.push_back(std::move(w));
    workers_.clear();
    for (auto& d : devices_) workers_.push_back(d.get());
    for (auto& r : remote_) workers_.push_back(r.get());
    shares_.assign(workers_.size(), DeviceShare{});
    for (size_t w = 0; w < workers_.size(); ++w) shares_[w].device = workers_[w]->name();
    latest_.assign(workers_.size(), RenderStats{});
    if (workers_.size() > 1 && !by_units_) {
        by_units_ = true;
        image_ = devices_[0]->film_state(); // zeroes, as every worker's film is
        holder_.assign(pixels(), kEveryWorker);
    }
}

void Renderer::render_to(uint32_t round_spp) {
    if (!by_units_) return devices_[0]->render_to(round_spp);
    round_start_ = std::chrono::steady_clock::now();
    in_round_ = true;
    render_units(round_spp);
    std::lock_guard<std::mutex> lock(progress_mutex_);
    in_round_ = false;
    seconds_ += since(round_start_);
}

void Renderer::render_pixels_to(const std::vector<uint32_t>& pixels, uint32_t from, uint32_t round_spp) {
    if (by_units_) throw std::logic_error("render_pixels_to: the image is rendered by units of work");
    devices_[0]->render_pixels_to(pixels, from, round_spp);
}

void Renderer::render_units(uint32_t round_spp) {
    WorkUnits units(pixels(), static_cast<uint32_t>(workers_.size()));
    std::atomic<bool> failed{false};
    std::vector<std::exception_ptr> errors(workers_.size());
    auto work = [&](size_t w) {
        UnitWorker& worker = *workers_[w];
        const bool local = w < devices_.size(); // a local device reports its own progress
        try {
            for (;;) {
                const PixelRun run = units.next(worker.most_pixels());
                if (run.count == 0 || failed) return;
                const auto start = std::chrono::steady_clock::now();
                const bool held = std::all_of(holder_.begin() + run.first, holder_.begin() + run.first + run.count,
                                              [&](int h) { return h == static_cast<int>(w) || h == kEveryWorker; });
                worker.render_unit(run.first, run.count, round_spp, image_, held);
                std::fill_n(holder_.begin() + run.first, run.count, static_cast<int>(w));
                const RenderStats counts = local ? RenderStats{} : worker.counts();
                std::lock_guard<std::mutex> lock(progress_mutex_);
                shares_[w].units += 1;
                shares_[w].busy_seconds += since(start);
                shares_[w].transfer_seconds = worker.transfer_seconds();
                if (!local) report_progress(w, counts);
                if (stop_requested(stop_)) return; // its integrator stopped too, within the unit
            }
        } catch (...) {
            errors[w] = std::current_exception();
            failed = true;
        }
    };
    if (workers_.size() == 1) {
        work(0);
    } else {
        std::vector<std::thread> threads;
        for (size_t w = 0; w < workers_.size(); ++w) threads.emplace_back(work, w);
        for (std::thread& t : threads) t.join();
    }
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

uint32_t Renderer::resume(const FilmState& state) {
    if (state.width != size_.width || state.height != size_.height)
        throw InputError("the partial render is " + std::to_string(state.width) + "x" + std::to_string(state.height) +
                         ", not " + std::to_string(size_.width) + "x" + std::to_string(size_.height));
    // One device goes on in place from counts its own pool left; any other
    // counts, and several workers, go on by units, which take each pixel from
    // wherever it stopped.
    if (by_units_ || !devices_[0]->resume(state)) {
        by_units_ = true;
        image_ = state;
        image_.bounce_layers = image_.aovs = 0; // a partial render keeps neither
        holder_.assign(pixels(), kNoWorker);
    }
    return state.samples.empty() ? 0 : *std::min_element(state.samples.begin(), state.samples.end());
}

void Renderer::report_progress(size_t w, const RenderStats& counts) {
    latest_[w] = counts;
    if (!progress_) return;
    RenderStats total;
    for (const RenderStats& part : latest_) total.add(part, false);
    total.seconds = seconds_ + (in_round_ ? since(round_start_) : 0.0);
    progress_(total);
}

void Renderer::on_progress(std::function<void(const RenderStats&)> f) {
    if (workers_.size() == 1) return devices_[0]->on_progress(std::move(f));
    progress_ = std::move(f);
    // Each local device reports from its own thread, with its own counts.
    for (size_t d = 0; d < devices_.size(); ++d)
        devices_[d]->on_progress([this, d](const RenderStats& s) {
            const RenderStats counts = s.without_counter_reads();
            std::lock_guard<std::mutex> lock(progress_mutex_);
            report_progress(d, counts);
        });
}

FilmReadout Renderer::read() const { return by_units_ ? resolve(image_) : devices_[0]->read(); }

FilmState Renderer::film_state() const { return by_units_ ? image_ : devices_[0]->film_state(); }

RenderStats Renderer::stats() const {
    if (!by_units_) return devices_[0]->stats();
    RenderStats total = devices_[0]->stats();
    for (size_t d = 1; d < devices_.size(); ++d) total.add(devices_[d]->stats(), true);
    for (const auto& r : remote_) total.add(r->counts(), false);
    std::lock_guard<std::mutex> lock(progress_mutex_);
    total.seconds = seconds_;
    return total;
}

RenderSummary Renderer::summary() const {
    RenderSummary s = devices_[0]->summary();
    if (workers_.size() == 1) return s;
    s.stats = stats();
    s.spp = static_cast<uint32_t>(s.stats.samples / pixels());
    s.device = std::to_string(workers_.size()) + " devices";
    s.shares = shares_;
    for (size_t d = 1; d < devices_.size(); ++d) {
        const RenderSummary part = devices_[d]->summary();
        s.device_bytes += part.device_bytes;
        s.times.kernel_build += part.times.kernel_build;
        s.kernels_from_cache = s.kernels_from_cache && part.kernels_from_cache;
        if (s.build_warning.empty()) s.build_warning = part.build_warning;
    }
    for (size_t w = 0; w < workers_.size(); ++w) s.shares[w].samples = workers_[w]->counts().samples;
    return s;
}

RenderOutput render_scene(const OpenClDevice& device, const Scene& scene, const SceneCamera& camera,
                          ImageSize size, const RenderSettings& settings) {
    Renderer renderer(device, scene, camera, size, settings);
    renderer.render_to(settings.spp);
    return RenderOutput{renderer.read(), renderer.summary()};
}

} // namespace wf
