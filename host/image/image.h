// image.h — an RGB float image in memory: what the film resolves to, what
// image files are read into and written from (image_io.h), and what error
// metrics compare (error_metrics.h).
#pragma once

#include <cstdint>
#include <vector>

namespace wf {

struct Image {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgb; // 3 floats per pixel, row-major from the top-left
};

} // namespace wf
