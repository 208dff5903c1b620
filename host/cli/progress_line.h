// progress_line.h — how far a render has come, on stderr while it runs:
// samples done, rays per second, elapsed time, time left and the estimated
// error at the last checkpoint. On a terminal one line rewritten in place a
// few times a second; otherwise a plain line every `period` seconds, for logs.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>

#include "integrator/path_integrator.h"

namespace wf {

class ProgressLine {
public:
    // `total_samples` 0: unknown (a time budget or a target error ends the
    // render); `time_budget` 0: none.
    ProgressLine(std::ostream& out, bool terminal, double period, uint64_t total_samples, double time_budget);

    // After every read of the device counters; prints when its period has passed.
    void update(const RenderStats& stats);
    void set_error(double relmse_estimate) { relmse_ = relmse_estimate; }
    // Clears a terminal's line before the closing report.
    void finish();

private:
    std::ostream& out_;
    bool terminal_;
    double period_;
    uint64_t total_;
    double budget_;
    std::chrono::steady_clock::time_point start_, last_;
    std::optional<double> relmse_;
    bool shown_ = false;
};

} // namespace wf
