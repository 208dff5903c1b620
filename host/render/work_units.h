// work_units.h — one round of a render over several devices or processes,
// cut into units of work: runs of pixels handed out in image order to
// whichever worker asks next, so a worker twice as fast takes twice the work.
// Runs shrink as the round nears its end (guided self-scheduling), so the
// workers finish together rather than one waiting on another's large last run.
//
// A pixel's samples are traced in sample order wherever its run goes, so how
// the image is cut changes no byte of it.
#pragma once

#include <cstdint>
#include <mutex>

namespace wf {

struct PixelRun {
    uint32_t first = 0, count = 0; // count 0: the round is handed out
};

class WorkUnits {
public:
    // Runs of at least `least` pixels (but the last) while the workers'
    // share of what is left allows.
    WorkUnits(uint32_t pixels, uint32_t workers, uint32_t least = 1024);

    // The next run, of at most `most` pixels (a worker's pool). Thread-safe.
    PixelRun next(uint32_t most);

private:
    std::mutex mutex_;
    uint32_t next_ = 0, pixels_, workers_, least_;
};

} // namespace wf
