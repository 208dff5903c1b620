// film.h — the per-pixel sums on the device that the kernels add to, and what
// they resolve to on the host: the mean radiance of each pixel, the variance
// of that mean (for the error estimate), and the per-bounce layers if kept.
#pragma once

#include <cstdint>
#include <vector>

#include <CL/opencl.hpp>

#include "image/image.h"
#include "wavefront/film_buffers.h"

namespace wf {

// The sums and counts exactly as the kernels hold them: what a render needs to
// go on where it stopped (host/film/partial_render.h). xyz of each float4 are used.
struct FilmState {
    uint32_t width = 0, height = 0;
    std::vector<cl_float4> sum, compensation, sum_squares, squares_compensation;
    std::vector<cl_uint> samples;
};

struct FilmReadout {
    Image mean;                      // linear radiance; black where a pixel has no sample yet
    Image variance_of_mean;          // s² / n per channel; 0 where n < 2
    std::vector<Image> bounce_layers; // radiance after 0, 1, ... reflections; the last open-ended
    uint32_t min_samples = 0;        // the fewest samples any pixel has
};

// Mean and variance of the mean of every pixel, from its sums.
FilmReadout resolve(const FilmState& state);

class Film {
public:
    Film(const cl::Context& context, const cl::CommandQueue& queue, uint32_t width, uint32_t height,
         uint32_t bounce_layers);

    FilmReadout read(const cl::CommandQueue& queue) const;
    FilmState state(const cl::CommandQueue& queue) const;
    // Replaces the sums and counts (the per-bounce layers are not part of a state).
    void restore(const cl::CommandQueue& queue, const FilmState& state) const;

    static size_t bytes_for(uint32_t width, uint32_t height, uint32_t bounce_layers);
    size_t bytes() const { return bytes_for(width, height, bounce_layers); }

    uint32_t width, height, bounce_layers;
    // One buffer per entry of include/wavefront/film_buffers.h, by its name
    // (the layers hold one element when there are none).
#define WF_FILM_MEMBER(type, name, what) cl::Buffer name;
    WF_FILM_BUFFERS(WF_FILM_MEMBER)
#undef WF_FILM_MEMBER
};

} // namespace wf
