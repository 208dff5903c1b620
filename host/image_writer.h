// image_writer.h — writing a rendered image through OpenImageIO, the format
// chosen by the file's extension: float linear radiance for .exr (and .hdr,
// .pfm, .tif), sRGB-encoded 8-bit for .png and .jpg and other 8-bit formats.
#pragma once

#include <string>

#include "film.h"

namespace wf {

struct ImageMetadata {
    unsigned samples_per_pixel = 0;
    double render_seconds = 0.0;
    std::string device;
    unsigned seed = 0;
    std::string scene;
};

// Throws InputError naming the file when it cannot be written.
void write_image(const std::string& path, const Image& image, const ImageMetadata& metadata);

// The sRGB transfer function (IEC 61966-2-1) of a linear value, clamped to [0, 1].
float srgb_encode(float linear);

} // namespace wf
