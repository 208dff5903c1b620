// film.cpp — the sums are cleared on creation and read back once per resolve.
#include "film.h"

namespace wf {

Film::Film(const cl::Context& context, const cl::CommandQueue& queue, uint32_t width_, uint32_t height_)
    : width(width_), height(height_) {
    const size_t pixels = size_t{width} * height;
    sum = cl::Buffer(context, CL_MEM_READ_WRITE, pixels * sizeof(cl_float4));
    compensation = cl::Buffer(context, CL_MEM_READ_WRITE, pixels * sizeof(cl_float4));
    samples = cl::Buffer(context, CL_MEM_READ_WRITE, pixels * sizeof(cl_uint));
    queue.enqueueFillBuffer(sum, 0.0f, 0, pixels * sizeof(cl_float4));
    queue.enqueueFillBuffer(compensation, 0.0f, 0, pixels * sizeof(cl_float4));
    queue.enqueueFillBuffer(samples, 0u, 0, pixels * sizeof(cl_uint));
}

Image Film::resolve(const cl::CommandQueue& queue) const {
    const size_t pixels = size_t{width} * height;
    std::vector<cl_float4> s(pixels), c(pixels);
    std::vector<cl_uint> n(pixels);
    queue.enqueueReadBuffer(sum, CL_FALSE, 0, pixels * sizeof(cl_float4), s.data());
    queue.enqueueReadBuffer(compensation, CL_FALSE, 0, pixels * sizeof(cl_float4), c.data());
    queue.enqueueReadBuffer(samples, CL_TRUE, 0, pixels * sizeof(cl_uint), n.data());
    Image image{width, height, std::vector<float>(3 * pixels, 0.0f)};
    for (size_t p = 0; p < pixels; ++p) {
        if (n[p] == 0) continue;
        for (int k = 0; k < 3; ++k)
            image.rgb[3 * p + k] =
                static_cast<float>((double(s[p].s[k]) + double(c[p].s[k])) / double(n[p]));
    }
    return image;
}

} // namespace wf
