// progress_line.cpp — rates are over the render's own time (stats.seconds
// covers finished rounds only), so the line uses its own clock.
#include "cli/progress_line.h"

#include <iomanip>
#include <sstream>

namespace wf {
namespace {

std::string clock_text(double seconds) {
    const auto s = static_cast<long long>(seconds + 0.5);
    std::ostringstream t;
    t << s / 3600 << ":" << std::setw(2) << std::setfill('0') << s / 60 % 60 << ":" << std::setw(2) << s % 60;
    return t.str();
}

} // namespace

ProgressLine::ProgressLine(std::ostream& out, bool terminal, double period, uint64_t total_samples,
                           double time_budget)
    : out_(out), terminal_(terminal), period_(terminal ? 0.25 : period), total_(total_samples), budget_(time_budget),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

void ProgressLine::update(const RenderStats& stats) {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_).count() < period_) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double rate = elapsed > 0.0 ? stats.samples / elapsed : 0.0;
    std::ostringstream line;
    line << std::fixed << std::setprecision(1) << "render: " << stats.samples * 1e-6 << " M samples";
    if (total_) line << " of " << total_ * 1e-6 << " M (" << 100.0 * stats.samples / total_ << "%)";
    line << ", " << std::setprecision(2) << (stats.closest_rays + stats.shadow_rays) / std::max(elapsed, 1e-9) * 1e-6
         << " M rays/s, elapsed " << clock_text(elapsed);
    double left = -1.0;
    if (total_ && rate > 0.0) left = (total_ - std::min<uint64_t>(stats.samples, total_)) / rate;
    if (budget_ > 0.0) left = left < 0.0 ? budget_ - elapsed : std::min(left, budget_ - elapsed);
    if (left >= 0.0) line << ", left " << clock_text(left);
    if (relmse_) line << ", relMSE est. " << std::scientific << std::setprecision(2) << *relmse_;
    if (terminal_) out_ << "\r\33[K" << line.str() << std::flush;
    else out_ << line.str() << "\n" << std::flush;
    shown_ = true;
}

void ProgressLine::finish() {
    if (terminal_ && shown_) out_ << "\r\33[K" << std::flush;
}

} // namespace wf
