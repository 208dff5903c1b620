// partial_render.cpp — the film's float4 sums go into RGB layers (their w is
// unused); a pixel's sample count into the three channels of one more, as
// floats, exact for every count --spp allows (at most 2^24).
#include "film/partial_render.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "base/errors.h"

namespace wf {
namespace {

const char* const kSumLayers[] = {"sum", "sumCompensation", "sumSquares", "squaresCompensation"};
const char* const kSamplesLayer = "samples";

// The film's sums in kSumLayers order.
template <class State> auto sums_of(State& film) {
    return std::array{&film.sum, &film.compensation, &film.sum_squares, &film.squares_compensation};
}

} // namespace

std::string partial_render_path(const std::string& output) { return output + ".partial.exr"; }

void write_partial_render(const std::string& path, const FilmState& film, const ImageMetadata& metadata) {
    const size_t pixels = size_t{film.width} * film.height;
    std::vector<ImageLayer> layers;
    for (int l = 0; l < 4; ++l) {
        Image image{film.width, film.height, std::vector<float>(3 * pixels), {}};
        const std::vector<cl_float4>& sums = *sums_of(film)[l];
        for (size_t p = 0; p < pixels; ++p)
            for (int k = 0; k < 3; ++k) image.rgb[3 * p + k] = sums[p].s[k];
        layers.push_back({kSumLayers[l], std::move(image)});
    }
    Image counts{film.width, film.height, std::vector<float>(3 * pixels), {}};
    for (size_t p = 0; p < pixels; ++p) std::fill_n(&counts.rgb[3 * p], 3, static_cast<float>(film.samples[p]));
    layers.push_back({kSamplesLayer, std::move(counts)});
    write_image(path, resolve(film).mean, metadata, layers);
}

void check_partial_options(const PartialRender& partial, const std::string& path, const ImageOptions& expected) {
    for (const auto& [name, value] : expected) {
        // A C++17 lambda cannot capture a structured binding (clang rejects it), only a copy of it.
        const auto it = std::find_if(partial.options.begin(), partial.options.end(),
                                     [&name = name](const auto& o) { return o.first == name; });
        const std::string found = it == partial.options.end() ? "nothing" : "'" + it->second + "'";
        if (it != partial.options.end() && it->second == value) continue;
        if (name == "scene-contents")
            throw InputError(path + ": was rendered from another scene (the scene file's contents differ)");
        throw InputError(path + ": was rendered with " + name + " " + found + ", this render has '" + value + "'");
    }
}

PartialRender read_partial_render(const std::string& path) {
    const ChannelImage image = read_channels(path);
    auto channel = [&](const std::string& name) {
        const auto it = std::find(image.channel_names.begin(), image.channel_names.end(), name);
        if (it == image.channel_names.end())
            throw InputError(path + ": not a partial render (no channel " + name + ")");
        return static_cast<size_t>(it - image.channel_names.begin());
    };
    PartialRender partial;
    FilmState& film = partial.film;
    film.width = image.width;
    film.height = image.height;
    const size_t pixels = size_t{image.width} * image.height, stride = image.channel_names.size();
    for (int l = 0; l < 4; ++l) {
        std::vector<cl_float4>& sums = *sums_of(film)[l];
        sums.assign(pixels, cl_float4{{0.0f, 0.0f, 0.0f, 0.0f}});
        for (int k = 0; k < 3; ++k) {
            const size_t c = channel(std::string(kSumLayers[l]) + "." + "RGB"[k]);
            for (size_t p = 0; p < pixels; ++p) sums[p].s[k] = image.pixels[p * stride + c];
        }
    }
    const size_t c = channel(std::string(kSamplesLayer) + ".R");
    film.samples.resize(pixels);
    for (size_t p = 0; p < pixels; ++p) {
        const float n = image.pixels[p * stride + c];
        if (!(n >= 0.0f && n <= float(1u << 24) && n == static_cast<float>(static_cast<uint32_t>(n))))
            throw InputError(path + ": pixel " + std::to_string(p) + " has no whole sample count");
        film.samples[p] = static_cast<uint32_t>(n);
    }
    partial.options = image.options;
    return partial;
}

} // namespace wf
