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

namespace wf {

// What the line counts towards.
struct ProgressGoal {
    uint64_t pixels = 1;
    uint32_t start_spp = 0;  // samples per pixel a resumed render starts from
    uint32_t max_spp = 0;    // 0: open (a time budget or a target error ends the render)
    double time_budget = 0.0; // seconds; 0: none
};

class ProgressLine {
public:
    // `period`: the least time between two lines (a terminal's: a few a second).
    ProgressLine(std::ostream& out, bool terminal, double period, const ProgressGoal& goal);

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
    ProgressGoal goal_;
    std::chrono::steady_clock::time_point start_, last_;
    std::optional<double> relmse_;
    bool shown_ = false;   // a terminal's line is on screen
    bool cleared_ = false; // erased since it was last shown: show it again at the next update
};

} // namespace wf
