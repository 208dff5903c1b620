// image.h — an RGB float image in memory: what the film resolves to, what
// image files are read into and written from (image_io.h), and what error
// metrics compare (error_metrics.h).
#pragma once

#include <cstdint>
#include <vector>

namespace wf {

// How an image read from an integer file (a PNG, a JPEG) was stored: scaled
// by 2^exposure, clipped to [0, 1] and rounded to `levels` steps, of the sRGB
// curve where `srgb`. An error against such a reference is measured after
// storing the render the same way (error_metrics.h).
struct Quantisation {
    uint32_t levels = 0; // 0: not quantised (a float file, or a render)
    bool srgb = false;
    float exposure = 0.0f;
};

struct Image {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgb; // 3 floats per pixel, row-major from the top-left
    Quantisation stored;    // how the file it came from held it
};

} // namespace wf
