// image_io.h — image files through OpenImageIO. Writing picks the format by
// the file's extension: float linear radiance for .exr (and .hdr, .pfm, .tif),
// sRGB-encoded 8-bit for .png, .jpg and other 8-bit formats. Reading takes the
// first three channels as linear floats (references for error reports).
#pragma once

#include <string>
#include <vector>

#include "film.h"

namespace wf {

struct ImageMetadata {
    unsigned samples_per_pixel = 0;
    double render_seconds = 0.0;
    std::string device;
    unsigned seed = 0;
    std::string scene;
};

// An extra set of channels written beside RGB, as "<name>.R", "<name>.G",
// "<name>.B"; only float formats can hold them.
struct ImageLayer {
    std::string name;
    Image image;
};

// Throws InputError naming the file when it cannot be written.
void write_image(const std::string& path, const Image& image, const ImageMetadata& metadata,
                 const std::vector<ImageLayer>& layers = {});

// True when the extension's format keeps linear float radiance (and layers).
bool holds_float_radiance(const std::string& path);

// Throws InputError naming the file when it cannot be read.
Image read_image(const std::string& path);

// The sRGB transfer function (IEC 61966-2-1) of a linear value, clamped to [0, 1].
float srgb_encode(float linear);

} // namespace wf
