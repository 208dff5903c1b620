// progress_line.cpp — rates are over the render's own time (stats.seconds
// covers finished rounds only), so the line uses its own clock.
#include "session/progress_line.h"

#include <algorithm>
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

ProgressLine::ProgressLine(std::ostream& out, bool terminal, double period, const ProgressGoal& goal)
    : out_(out), terminal_(terminal), period_(period), goal_(goal), start_(std::chrono::steady_clock::now()),
      last_(start_) {
    goal_.pixels = std::max<uint64_t>(goal_.pixels, 1);
}

void ProgressLine::update(const RenderStats& stats) {
    const auto now = std::chrono::steady_clock::now();
    if (!cleared_ && std::chrono::duration<double>(now - last_).count() < period_) return;
    last_ = now;
    cleared_ = false;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    // Samples finished in this run, as whole samples per pixel on top of where it started.
    const uint64_t spp = goal_.start_spp + stats.samples / goal_.pixels;
    std::ostringstream line;
    line << "render: " << spp;
    if (goal_.max_spp) line << "/" << goal_.max_spp;
    line << " spp";
    if (goal_.start_spp) line << " (resumed from " << goal_.start_spp << ")";
    line << ", " << std::fixed << std::setprecision(2)
         << (stats.closest_rays + stats.shadow_rays) / std::max(elapsed, 1e-9) * 1e-6 << " M rays/s, elapsed "
         << clock_text(elapsed);
    const double rate = elapsed > 0.0 ? stats.samples / elapsed : 0.0;
    const uint64_t total = goal_.max_spp ? goal_.pixels * (goal_.max_spp - std::min(goal_.start_spp, goal_.max_spp)) : 0;
    double left = -1.0;
    if (total && rate > 0.0) left = (total - std::min<uint64_t>(stats.samples, total)) / rate;
    if (goal_.time_budget > 0.0)
        left = left < 0.0 ? goal_.time_budget - elapsed : std::min(left, goal_.time_budget - elapsed);
    if (left >= 0.0) line << ", left " << clock_text(left);
    if (relmse_) line << ", relMSE est. " << std::scientific << std::setprecision(2) << *relmse_;
    if (terminal_) out_ << "\r\33[K" << line.str() << std::flush;
    else out_ << line.str() << "\n" << std::flush;
    shown_ = terminal_;
}

void ProgressLine::clear() {
    if (!shown_) return;
    out_ << "\r\33[K" << std::flush;
    shown_ = false;
    cleared_ = true;
}

} // namespace wf
