// film.h — the per-pixel sums on the device that the kernels add to, and what
// they resolve to on the host: the mean radiance of each pixel, the variance
// of that mean (for the error estimate), and the per-bounce layers if kept.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "image/image.h"
#include "wavefront/film_buffers.h"

namespace wf {

// The host types of the film's elements (include/wavefront/film_buffers.h).
namespace film_element {
using float4 = cl_float4;
using uint32_t = cl_uint;
} // namespace film_element

// The sums and counts exactly as the kernels hold them, one vector per film
// buffer: what a render needs to go on where it stopped
// (host/film/partial_render.h), and the image that a render over several
// devices gathers. xyz of each float4 are used; the layers and AOVs are
// empty when none are kept, and a partial render keeps neither.
struct FilmState {
    uint32_t width = 0, height = 0, bounce_layers = 0;
    uint32_t aovs = 0; // WF_AOV_* bits
#define WF_FILM_STATE_MEMBER(type, name, extent, what) std::vector<film_element::type> name;
    WF_FILM_BUFFERS(WF_FILM_STATE_MEMBER)
#undef WF_FILM_STATE_MEMBER
};

// Pixels [first, first + count) of every buffer of `state`, buffer by buffer
// and plane by plane, as bytes: a unit's sums sent to another MPI rank. The
// unpacking writes them to the same pixels of `state`, which has the image's
// size, and returns the bytes it read.
std::vector<unsigned char> pack_pixels(const FilmState& state, uint32_t first, uint32_t count);
size_t unpack_pixels(const unsigned char* bytes, size_t size, uint32_t first, uint32_t count, FilmState& state);

struct FilmReadout {
    Image mean;                      // linear radiance; black where a pixel has no sample yet
    Image variance_of_mean;          // s² / n per channel; 0 where n < 2
    std::vector<Image> bounce_layers; // radiance after 0, 1, ... reflections; the last open-ended
    // The first hit's mean base colour, shading normal and distance (the
    // distance in every channel), where the render keeps them (WF_AOV_*).
    std::optional<Image> albedo, normal, depth;
    std::optional<Image> samples; // each pixel's count in every channel (WF_AOV_SAMPLES)
    uint32_t min_samples = 0;        // the fewest samples any pixel has
    uint32_t max_samples = 0;        // the most: more than the fewest where adaptive sampling stopped pixels apart
    double mean_samples = 0.0;
};

// What bounce layer `index` of `count` is called in files and in Python:
// bounce0, bounce1, ..., the last open-ended one bounce7plus.
std::string bounce_layer_name(size_t index, size_t count);

// Mean and variance of the mean of every pixel, from its sums; the bounce
// layers and AOVs where the state holds them.
FilmReadout resolve(const FilmState& state);

class Film {
public:
    Film(const cl::Context& context, const cl::CommandQueue& queue, uint32_t width, uint32_t height,
         uint32_t bounce_layers, uint32_t aovs = 0);

    FilmReadout read(const cl::CommandQueue& queue) const { return resolve(state(queue)); }
    // Every buffer, the layers included.
    FilmState state(const cl::CommandQueue& queue) const;
    // Replaces the sums and counts, and the layers if `state` holds them.
    void restore(const cl::CommandQueue& queue, const FilmState& state) const;

    // Pixels [first, first + count) of every buffer, between the device and
    // the same pixels of `state`, which has this film's size: the film of a
    // unit of work (render/renderer.h). Writing leaves the layers as they
    // are when `state` has none.
    void read_pixels(const cl::CommandQueue& queue, uint32_t first, uint32_t count, FilmState& state) const;
    void write_pixels(const cl::CommandQueue& queue, uint32_t first, uint32_t count, const FilmState& state) const;

    static size_t bytes_for(uint32_t width, uint32_t height, uint32_t bounce_layers, uint32_t aovs = 0);
    size_t bytes() const { return bytes_for(width, height, bounce_layers, aovs); }

    uint32_t width, height, bounce_layers, aovs;
    // One buffer per entry of include/wavefront/film_buffers.h, by its name
    // (the layers and AOVs hold one element when there are none).
#define WF_FILM_MEMBER(type, name, extent, what) cl::Buffer name;
    WF_FILM_BUFFERS(WF_FILM_MEMBER)
#undef WF_FILM_MEMBER
};

} // namespace wf
