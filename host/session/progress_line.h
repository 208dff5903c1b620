// progress_line.h — how far a render has come, on stderr while it runs:
// samples per pixel done of those asked ("32/256 spp", as renderers count),
// rays per second, elapsed time, time left and the estimated error at the
// last checkpoint. On a terminal one line rewritten in place a few times a
// second, erased while anything else is printed; otherwise a plain line every
// `period` seconds, for logs.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>

#include "integrator/path_integrator.h"
#include "render/progress_options.h"

namespace wf {

class ProgressLine {
public:
    // `period`: the least time between two lines (a terminal's: a few a
    // second). The line counts towards `spp` samples on each of `pixels`
    // (RenderSettings::spp; 0: open, a time budget or a target error ends the
    // render) from `progress.start_spp`, within `progress.time_budget`.
    ProgressLine(std::ostream& out, bool terminal, double period, uint64_t pixels, uint32_t spp,
                 const ProgressOptions& progress);

    // After every read of the device counters; prints when its period has
    // passed, or at once after clear().
    void update(const RenderStats& stats);
    void set_error(double relmse_estimate) { relmse_ = relmse_estimate; }
    // Erases a terminal's line, so that a whole line printed next (a
    // checkpoint row on stdout, the closing report) is not written into it.
    void clear();

private:
    std::ostream& out_;
    bool terminal_;
    double period_;
    uint64_t pixels_;
    uint32_t spp_, start_spp_;
    double time_budget_;
    std::chrono::steady_clock::time_point start_, last_;
    std::optional<double> relmse_;
    bool shown_ = false;   // a terminal's line is on screen
    bool cleared_ = false; // erased since it was last shown: show it again at the next update
};

} // namespace wf
