// film.cpp — buffers are zeroed on creation; a read resolves the sums in
// double, adding each sum's compensation to it. Every transfer walks
// WF_FILM_BUFFERS, so a buffer added there moves with the rest.
#include "film/film.h"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>

#include "wavefront/aovs.h"

// Planes of one element per pixel in a buffer of each extent (film_buffers.h).
#define WF_FILM_PLANES_PIXEL(bounce_layers, aovs) 1u
#define WF_FILM_PLANES_LAYER(bounce_layers, aovs) (bounce_layers)
#define WF_FILM_PLANES_AOV(bounce_layers, aovs) (((aovs) & WF_AOV_FIRST_HIT) ? 1u : 0u)
// Whether a state may leave the buffer out (a partial render keeps neither layers nor AOVs).
#define WF_FILM_OPTIONAL_PIXEL false
#define WF_FILM_OPTIONAL_LAYER true
#define WF_FILM_OPTIONAL_AOV true

namespace wf {
namespace {

template <typename T>
void read_planes(const cl::CommandQueue& queue, const cl::Buffer& buffer, size_t pixels, uint32_t planes,
                 uint32_t first, uint32_t count, std::vector<T>& into) {
    if (into.size() != pixels * planes) into.assign(pixels * planes, T{});
    for (size_t plane = 0; plane < planes; ++plane) {
        const size_t at = plane * pixels + first;
        queue.enqueueReadBuffer(buffer, CL_FALSE, at * sizeof(T), count * sizeof(T), into.data() + at);
    }
}

template <typename T>
void write_planes(const cl::CommandQueue& queue, const cl::Buffer& buffer, size_t pixels, uint32_t planes,
                  uint32_t first, uint32_t count, const std::vector<T>& from, bool optional) {
    if (from.empty() && optional) return; // layers or AOVs a state does not keep
    if (from.size() != pixels * planes) throw std::logic_error("a film state of another size");
    for (size_t plane = 0; plane < planes; ++plane) {
        const size_t at = plane * pixels + first;
        queue.enqueueWriteBuffer(buffer, CL_FALSE, at * sizeof(T), count * sizeof(T), from.data() + at);
    }
}

template <typename T>
void pack_planes(const std::vector<T>& from, size_t pixels, uint32_t planes, uint32_t first, uint32_t count,
                 std::vector<unsigned char>& out) {
    if (from.size() != pixels * planes) return; // layers a state does not keep
    for (size_t plane = 0; plane < planes; ++plane) {
        const auto* begin = reinterpret_cast<const unsigned char*>(from.data() + plane * pixels + first);
        out.insert(out.end(), begin, begin + count * sizeof(T));
    }
}

template <typename T>
size_t unpack_planes(const unsigned char* bytes, size_t size, size_t pixels, uint32_t planes, uint32_t first,
                     uint32_t count, std::vector<T>& into) {
    if (into.size() != pixels * planes) return 0;
    const size_t plane_bytes = count * sizeof(T);
    if (size < planes * plane_bytes) throw std::runtime_error("a unit's sums arrived short");
    for (size_t plane = 0; plane < planes; ++plane)
        std::memcpy(into.data() + plane * pixels + first, bytes + plane * plane_bytes, plane_bytes);
    return planes * plane_bytes;
}

} // namespace

std::vector<unsigned char> pack_pixels(const FilmState& st, uint32_t first, uint32_t count) {
    const size_t pixels = size_t{st.width} * st.height;
    std::vector<unsigned char> out;
#define WF_FILM_PACK(type, name, extent, what) \
    pack_planes(st.name, pixels, WF_FILM_PLANES_##extent(st.bounce_layers, st.aovs), first, count, out);
    WF_FILM_BUFFERS(WF_FILM_PACK)
#undef WF_FILM_PACK
    return out;
}

size_t unpack_pixels(const unsigned char* bytes, size_t size, uint32_t first, uint32_t count, FilmState& st) {
    const size_t pixels = size_t{st.width} * st.height;
    size_t read = 0;
#define WF_FILM_UNPACK(type, name, extent, what)                                                             \
    read += unpack_planes(bytes + read, size - read, pixels, WF_FILM_PLANES_##extent(st.bounce_layers, st.aovs), first, \
                          count, st.name);
    WF_FILM_BUFFERS(WF_FILM_UNPACK)
#undef WF_FILM_UNPACK
    return read;
}

size_t Film::bytes_for(uint32_t width, uint32_t height, uint32_t bounce_layers, uint32_t aovs) {
    const size_t pixels = size_t{width} * height;
    size_t bytes = 0;
#define WF_FILM_BYTES(type, name, extent, what) \
    bytes += std::max<size_t>(1, pixels * WF_FILM_PLANES_##extent(bounce_layers, aovs)) * sizeof(film_element::type);
    WF_FILM_BUFFERS(WF_FILM_BYTES)
#undef WF_FILM_BYTES
    return bytes;
}

Film::Film(const cl::Context& context, const cl::CommandQueue& queue, uint32_t width_, uint32_t height_,
           uint32_t bounce_layers_, uint32_t aovs_)
    : width(width_), height(height_), bounce_layers(bounce_layers_), aovs(aovs_) {
    const size_t pixels = size_t{width} * height;
#define WF_FILM_ALLOCATE(type, name, extent, what)                                                           \
    {                                                                                                       \
        const size_t bytes =                                                                                \
            std::max<size_t>(1, pixels * WF_FILM_PLANES_##extent(bounce_layers, aovs)) * sizeof(film_element::type); \
        name = cl::Buffer(context, CL_MEM_READ_WRITE, bytes);                                               \
        queue.enqueueFillBuffer(name, cl_uchar{0}, 0, bytes);                                               \
    }
    WF_FILM_BUFFERS(WF_FILM_ALLOCATE)
#undef WF_FILM_ALLOCATE
}

void Film::read_pixels(const cl::CommandQueue& queue, uint32_t first, uint32_t count, FilmState& st) const {
    const size_t pixels = size_t{width} * height;
    st.width = width;
    st.height = height;
    st.bounce_layers = bounce_layers;
    st.aovs = aovs;
#define WF_FILM_READ(type, name, extent, what) \
    read_planes(queue, name, pixels, WF_FILM_PLANES_##extent(bounce_layers, aovs), first, count, st.name);
    WF_FILM_BUFFERS(WF_FILM_READ)
#undef WF_FILM_READ
    queue.finish();
}

void Film::write_pixels(const cl::CommandQueue& queue, uint32_t first, uint32_t count, const FilmState& st) const {
    const size_t pixels = size_t{width} * height;
    if (st.width != width || st.height != height) throw std::logic_error("a film state of another size");
#define WF_FILM_WRITE(type, name, extent, what) \
    write_planes(queue, name, pixels, WF_FILM_PLANES_##extent(bounce_layers, aovs), first, count, st.name, \
                 WF_FILM_OPTIONAL_##extent);
    WF_FILM_BUFFERS(WF_FILM_WRITE)
#undef WF_FILM_WRITE
    queue.finish();
}

FilmState Film::state(const cl::CommandQueue& queue) const {
    FilmState st;
    read_pixels(queue, 0, width * height, st);
    return st;
}

void Film::restore(const cl::CommandQueue& queue, const FilmState& st) const { write_pixels(queue, 0, width * height, st); }

std::string bounce_layer_name(size_t index, size_t count) {
    return "bounce" + std::to_string(index) + (index + 1 == count ? "plus" : "");
}

FilmReadout resolve(const FilmState& st) {
    const size_t pixels = size_t{st.width} * st.height;
    const std::vector<cl_float4>&s = st.sum, &c = st.compensation, &s2 = st.sum_squares, &c2 = st.squares_compensation;
    const std::vector<cl_uint>& n = st.samples;
    FilmReadout out;
    out.mean = Image{st.width, st.height, std::vector<float>(3 * pixels, 0.0f), {}};
    out.variance_of_mean = out.mean;
    out.min_samples = pixels ? *std::min_element(n.begin(), n.end()) : 0;
    out.max_samples = pixels ? *std::max_element(n.begin(), n.end()) : 0;
    out.mean_samples = pixels ? std::accumulate(n.begin(), n.end(), 0.0) / pixels : 0.0;
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
    if (st.aovs & WF_AOV_SAMPLES) {
        out.samples = Image{st.width, st.height, std::vector<float>(3 * pixels), {}};
        for (size_t p = 0; p < 3 * pixels; ++p) out.samples->rgb[p] = static_cast<float>(n[p / 3]);
    }
    if ((st.aovs & WF_AOV_FIRST_HIT) && st.aov_albedo.size() == pixels) {
        auto mean_of = [&](const std::vector<cl_float4>& sums, auto value) {
            Image image{st.width, st.height, std::vector<float>(3 * pixels, 0.0f), {}};
            for (size_t p = 0; p < pixels; ++p)
                for (int k = 0; k < 3 && n[p]; ++k) image.rgb[3 * p + k] = value(sums[p], k) / float(n[p]);
            return image;
        };
        if (st.aovs & WF_AOV_ALBEDO) out.albedo = mean_of(st.aov_albedo, [](cl_float4 v, int k) { return v.s[k]; });
        if (st.aovs & WF_AOV_NORMAL) out.normal = mean_of(st.aov_normal_depth, [](cl_float4 v, int k) { return v.s[k]; });
        if (st.aovs & WF_AOV_DEPTH) out.depth = mean_of(st.aov_normal_depth, [](cl_float4 v, int) { return v.s[3]; });
    }
    if (st.layers.size() != pixels * st.bounce_layers) return out; // not kept
    for (uint32_t l = 0; l < st.bounce_layers; ++l) {
        Image layer{st.width, st.height, std::vector<float>(3 * pixels, 0.0f), {}};
        for (size_t p = 0; p < pixels; ++p)
            for (int k = 0; k < 3 && n[p]; ++k)
                layer.rgb[3 * p + k] = static_cast<float>(
                    (double(st.layers[l * pixels + p].s[k]) + double(st.layer_compensation[l * pixels + p].s[k])) /
                    n[p]);
        out.bounce_layers.push_back(std::move(layer));
    }
    return out;
}

} // namespace wf
