// progressive_render.cpp — round sizes: doubling by default; with
// --report-every, as many samples as the measured rate fits in that time; and
// never more than the time budget has left. The rate is per sample, so that a
// round of adaptive sampling's fewer pixels is expected to take less time.
// Rounds change nothing in the image (wavefront_integrator.h), only when the
// film is looked at.
#include "render/progressive_render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include "base/errors.h"
#include "render/adaptive_sampling.h"

namespace wf {
namespace {

constexpr uint32_t kUnlimitedSpp = 1u << 24;
// Below this many samples a pixel's variance says too little to stop on.
constexpr uint32_t kMinSppForTargetError = 16;

// The sample count the next round should reach, or `done` when none fits.
uint32_t next_round(const ProgressOptions& o, uint32_t spp, uint32_t done, double seconds_per_spp, double elapsed) {
    const uint32_t limit = spp ? spp : kUnlimitedSpp;
    uint32_t next = done == 0 ? 1u : 2u * done;
    if (o.report_every > 0.0 && seconds_per_spp > 0.0)
        next = done + std::max(1u, static_cast<uint32_t>(std::min(o.report_every / seconds_per_spp, double(limit))));
    if (o.time_budget > 0.0 && seconds_per_spp > 0.0) {
        const double fits = std::floor((o.time_budget - elapsed) / seconds_per_spp);
        if (fits < 1.0) return done;
        next = std::min(next, done + static_cast<uint32_t>(std::min(fits, double(limit))));
    }
    return std::min(next, limit);
}

} // namespace

FilmReadout render_progressively(Renderer& renderer, uint32_t spp, const ProgressOptions& options,
                                 const std::function<void(const Checkpoint&)>& on_checkpoint) {
    if (options.adaptive && !renderer.renders_in_place())
        throw InputError("--adaptive samples the image on one device, and goes on only from a partial render of "
                         "the same pool size: not over several devices or ranks");
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    FilmReadout film;
    uint32_t done = options.start_spp;
    // With --adaptive, from kMinSppForTargetError on, the pixels that go on
    // (`listed` once it has chosen); until then every pixel takes every round.
    const ImageSize size = renderer.size();
    std::optional<AdaptiveSampling> adaptive;
    if (options.adaptive) adaptive.emplace(size.width, size.height, options.target_relmse);
    bool listed = false;
    uint32_t sampling = size.width * size.height;
    for (;;) {
        const RenderStats stats = renderer.stats(); // this run's: a resumed render's earlier samples are not in it
        const double seconds_per_spp = stats.samples ? stats.seconds / double(stats.samples) * sampling : 0.0;
        const uint32_t next = next_round(options, spp, done, seconds_per_spp, elapsed());
        if (next <= done) break;
        if (listed) renderer.render_pixels_to(adaptive->going_on(), done, next);
        else renderer.render_to(next);
        film = renderer.read();
        const bool stopped = stop_requested(options.stop);
        // Stopped within a round, the pixels adaptive sampling continued have between `done` and `next`.
        done = stopped ? (listed ? done : film.min_samples) : next;
        if (adaptive && !stopped && done >= kMinSppForTargetError) {
            adaptive->update(film, done);
            listed = true;
            sampling = static_cast<uint32_t>(adaptive->going_on().size());
        }

        Checkpoint c;
        c.seconds = elapsed();
        c.spp = done;
        c.pixels_sampling = sampling;
        if (options.reference) c.error = compare_images(film.mean, *options.reference);
        if (done >= 2) c.relmse_estimate = estimate_relmse(film.mean, film.variance_of_mean);
        on_checkpoint(c);

        const bool time_is_up = options.time_budget > 0.0 && c.seconds >= options.time_budget;
        // The image's error. Adaptive sampling stops its last pixels about when
        // the image meets the target (adaptive_sampling.h), and then nothing is left to render.
        const bool accurate = options.target_relmse > 0.0 && done >= kMinSppForTargetError &&
                              (*c.relmse_estimate < options.target_relmse || sampling == 0);
        if (time_is_up || accurate || stopped) break;
    }
    return film;
}

} // namespace wf
