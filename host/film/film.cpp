// film.cpp — buffers are zeroed on creation; a read resolves the sums in
// double, adding each sum's compensation to it.
#include "film/film.h"

#include <algorithm>

namespace wf {
namespace {

cl::Buffer zeroed(const cl::Context& context, const cl::CommandQueue& queue, size_t bytes) {
    cl::Buffer b(context, CL_MEM_READ_WRITE, bytes);
    queue.enqueueFillBuffer(b, cl_uchar{0}, 0, bytes);
    return b;
}

std::vector<cl_float4> read_float4(const cl::CommandQueue& queue, const cl::Buffer& b, size_t count) {
    std::vector<cl_float4> v(count);
    queue.enqueueReadBuffer(b, CL_TRUE, 0, count * sizeof(cl_float4), v.data());
    return v;
}

} // namespace

size_t Film::bytes_for(uint32_t width, uint32_t height, uint32_t bounce_layers) {
    const size_t pixels = size_t{width} * height;
    return pixels * (4 * sizeof(cl_float4) + sizeof(cl_uint)) +
           std::max<size_t>(1, pixels * bounce_layers) * 2 * sizeof(cl_float4);
}

Film::Film(const cl::Context& context, const cl::CommandQueue& queue, uint32_t width_, uint32_t height_,
           uint32_t bounce_layers_)
    : width(width_), height(height_), bounce_layers(bounce_layers_) {
    const size_t pixels = size_t{width} * height;
    sum = zeroed(context, queue, pixels * sizeof(cl_float4));
    compensation = zeroed(context, queue, pixels * sizeof(cl_float4));
    sum_squares = zeroed(context, queue, pixels * sizeof(cl_float4));
    squares_compensation = zeroed(context, queue, pixels * sizeof(cl_float4));
    samples = zeroed(context, queue, pixels * sizeof(cl_uint));
    const size_t layer_elements = std::max<size_t>(1, pixels * bounce_layers);
    layers = zeroed(context, queue, layer_elements * sizeof(cl_float4));
    layer_compensation = zeroed(context, queue, layer_elements * sizeof(cl_float4));
}

FilmState Film::state(const cl::CommandQueue& queue) const {
    const size_t pixels = size_t{width} * height;
    FilmState st;
    st.width = width;
    st.height = height;
    st.sum = read_float4(queue, sum, pixels);
    st.compensation = read_float4(queue, compensation, pixels);
    st.sum_squares = read_float4(queue, sum_squares, pixels);
    st.squares_compensation = read_float4(queue, squares_compensation, pixels);
    st.samples.resize(pixels);
    queue.enqueueReadBuffer(samples, CL_TRUE, 0, pixels * sizeof(cl_uint), st.samples.data());
    return st;
}

void Film::restore(const cl::CommandQueue& queue, const FilmState& st) const {
    const size_t pixels = size_t{width} * height;
    queue.enqueueWriteBuffer(sum, CL_TRUE, 0, pixels * sizeof(cl_float4), st.sum.data());
    queue.enqueueWriteBuffer(compensation, CL_TRUE, 0, pixels * sizeof(cl_float4), st.compensation.data());
    queue.enqueueWriteBuffer(sum_squares, CL_TRUE, 0, pixels * sizeof(cl_float4), st.sum_squares.data());
    queue.enqueueWriteBuffer(squares_compensation, CL_TRUE, 0, pixels * sizeof(cl_float4),
                             st.squares_compensation.data());
    queue.enqueueWriteBuffer(samples, CL_TRUE, 0, pixels * sizeof(cl_uint), st.samples.data());
}

FilmReadout resolve(const FilmState& st) {
    const size_t pixels = size_t{st.width} * st.height;
    const std::vector<cl_float4>&s = st.sum, &c = st.compensation, &s2 = st.sum_squares, &c2 = st.squares_compensation;
    const std::vector<cl_uint>& n = st.samples;
    FilmReadout out;
    out.mean = Image{st.width, st.height, std::vector<float>(3 * pixels, 0.0f)};
    out.variance_of_mean = out.mean;
    out.min_samples = pixels ? *std::min_element(n.begin(), n.end()) : 0;
    for (size_t p = 0; p < pixels; ++p) {
        if (n[p] == 0) continue;
        const double count = n[p];
        for (int k = 0; k < 3; ++k) {
            const double mean = (double(s[p].s[k]) + double(c[p].s[k])) / count;
            out.mean.rgb[3 * p + k] = static_cast<float>(mean);
            if (n[p] < 2) continue;
            const double squares = double(s2[p].s[k]) + double(c2[p].s[k]);
            const double sample_variance = std::max(0.0, (squares - count * mean * mean) / (count - 1.0));
            out.variance_of_mean.rgb[3 * p + k] = static_cast<float>(sample_variance / count);
        }
    }
    return out;
}

FilmReadout Film::read(const cl::CommandQueue& queue) const {
    const size_t pixels = size_t{width} * height;
    const FilmState st = state(queue);
    const std::vector<cl_uint>& n = st.samples;
    FilmReadout out = resolve(st);
    if (bounce_layers) {
        const std::vector<cl_float4> ls = read_float4(queue, layers, pixels * bounce_layers),
                                     lc = read_float4(queue, layer_compensation, pixels * bounce_layers);
        for (uint32_t l = 0; l < bounce_layers; ++l) {
            Image layer{width, height, std::vector<float>(3 * pixels, 0.0f)};
            for (size_t p = 0; p < pixels; ++p)
                for (int k = 0; k < 3 && n[p]; ++k)
                    layer.rgb[3 * p + k] = static_cast<float>(
                        (double(ls[l * pixels + p].s[k]) + double(lc[l * pixels + p].s[k])) / n[p]);
            out.bounce_layers.push_back(std::move(layer));
        }
    }
    return out;
}

} // namespace wf
