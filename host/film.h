// film.h — the per-pixel sums on the device that accumulate.cl adds to, and
// the image they resolve to: mean radiance per pixel, linear, RGB.
#pragma once

#include <cstdint>
#include <vector>

#include <CL/opencl.hpp>

namespace wf {

struct Image {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgb; // 3 floats per pixel, row-major from the top-left
};

class Film {
public:
    Film(const cl::Context& context, const cl::CommandQueue& queue, uint32_t width, uint32_t height);

    // The mean of each pixel's samples so far (black where it has none).
    Image resolve(const cl::CommandQueue& queue) const;

    uint32_t width, height;
    cl::Buffer sum;          // float4 per pixel
    cl::Buffer compensation; // float4 per pixel: the low part of sum
    cl::Buffer samples;      // uint per pixel
    static size_t bytes_for(uint32_t width, uint32_t height) {
        return size_t{width} * height * (2 * sizeof(cl_float4) + sizeof(cl_uint));
    }
    size_t bytes() const { return bytes_for(width, height); }
};

} // namespace wf
