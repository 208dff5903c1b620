// adaptive_sampling.h — which pixels take the next round (--adaptive). The
// image's relMSE is the mean of its pixels' (error_metrics.h); for a given
// number of samples it is least when each pixel has samples in proportion to
// the square root of its per-sample variance v, so that one more sample buys
// the same drop in error wherever it goes. From a minimum on, a pixel with n
// samples therefore goes on while v ≥ λn², with λ = (target / mean √v)²:
// the allocation that would bring the image to the target with the fewest
// samples. Each v is estimated from the pixel's own samples, averaged over its
// 3×3 neighbourhood, which keeps a pixel whose few samples happen to agree
// (all of them missing a small light) from stopping on its own. The render
// still ends when the image's estimated error is below the target
// (progressive_render.h): adaptive sampling changes only which pixels get there.
//
// A pixel that stopped never starts again, so every pixel going on has the
// samples of the round it last took part in: the next round continues them
// all from one count (Renderer::render_pixels_to). Each pixel's samples are
// those a uniform render takes, so a pixel that stopped at N samples has the
// bytes of a uniform render of N, and the same flags and seed stop the same
// pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "film/film.h"

namespace wf {

class AdaptiveSampling {
public:
    AdaptiveSampling(uint32_t width, uint32_t height, double target);

    // After a round that took every pixel going on to `samples`: which go on from here.
    void update(const FilmReadout& film, uint32_t samples);
    // Ascending pixel indices; every pixel until the first update().
    const std::vector<uint32_t>& going_on() const { return going_on_; }
    // The samples each pixel has had, as of the last update().
    const std::vector<uint32_t>& samples() const { return samples_; }

private:
    uint32_t width_, height_;
    double target_;
    std::vector<uint32_t> going_on_, samples_;
};

} // namespace wf
