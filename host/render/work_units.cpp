// work_units.cpp — each run is half a worker's share of what is left.
#include "render/work_units.h"

#include <algorithm>

namespace wf {

WorkUnits::WorkUnits(uint32_t pixels, uint32_t workers, uint32_t least)
    : pixels_(pixels), workers_(std::max(workers, 1u)), least_(std::max(least, 1u)) {}

PixelRun WorkUnits::next(uint32_t most) {
    std::lock_guard<std::mutex> lock(mutex_);
    const uint32_t left = pixels_ - next_;
    const uint32_t share = std::max(left / (2 * workers_), least_);
    const PixelRun run{next_, std::min({left, share, std::max(most, 1u)})};
    next_ += run.count;
    return run;
}

} // namespace wf
