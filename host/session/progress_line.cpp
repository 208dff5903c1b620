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

ProgressLine::ProgressLine(std::ostream& out, bool terminal, double period, uint64_t pixels, uint32_t spp,
                           const ProgressOptions& progress)
    : out_(out), terminal_(terminal), period_(period), pixels_(std::max<uint64_t>(pixels, 1)), spp_(spp),
      start_spp_(progress.start_spp), time_budget_(progress.time_budget), start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void ProgressLine::update(const RenderStats& stats) {
    const auto now = std::chrono::steady_clock::now();
    if (!cleared_ && std::chrono::duration<double>(now - last_).count() < period_) return;
    last_ = now;
    cleared_ = false;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    // Samples finished in this run, as whole samples per pixel on top of where it started.
    const uint64_t spp = start_spp_ + stats.samples / pixels_;
    std::ostringstream line;
    line << "render: " << spp;
    if (spp_) line << "/" << spp_;
    line << " spp";
    if (start_spp_) line << " (resumed from " << start_spp_ << ")";
    line << ", " << std::fixed << std::setprecision(2)
         << (stats.closest_rays + stats.shadow_rays) / std::max(elapsed, 1e-9) * 1e-6 << " M rays/s, elapsed "
         << clock_text(elapsed);
    const double rate = elapsed > 0.0 ? stats.samples / elapsed : 0.0;
    const uint64_t total = spp_ ? pixels_ * (spp_ - std::min(start_spp_, spp_)) : 0;
    double left = -1.0;
    if (total && rate > 0.0) left = (total - std::min<uint64_t>(stats.samples, total)) / rate;
    if (time_budget_ > 0.0)
        left = left < 0.0 ? time_budget_ - elapsed : std::min(left, time_budget_ - elapsed);
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
