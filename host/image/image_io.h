// image_io.h — image files through OpenImageIO. Writing picks the format by
// the file's extension: float linear radiance for .exr (and .hdr, .tif),
// sRGB-encoded 8-bit for .png, .jpg and other 8-bit formats; it writes a
// temporary file beside the target and renames it, so a crash or a full disk
// never leaves a torn image. Reading takes the first three channels as linear
// floats (references for error reports; 8-bit sRGB files are decoded to
// linear), or every channel by name.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace wf {

// What shaped an image, as "name" -> value; written as wavefront:option:name.
using ImageOptions = std::vector<std::pair<std::string, std::string>>;

struct ImageMetadata {
    unsigned samples_per_pixel = 0; // the fewest any pixel has
    double render_seconds = 0.0;
    std::string device;
    unsigned seed = 0;
    std::string scene;
    bool interrupted = false; // stopped before its sample count: pixels may differ by one sample
    ImageOptions options;
};

// An extra set of channels written beside RGB, as "<name>.<channel>" (R, G, B
// unless named otherwise) from each pixel's first channels.size() values;
// only float formats can hold them.
struct ImageLayer {
    std::string name;
    Image image;
    std::vector<std::string> channels{"R", "G", "B"};
};

// How the values are stored: float formats as 32-bit floats or, with
// `half`, 16-bit halves; 8-bit formats scaled by 2^exposure before the sRGB curve.
struct ImageEncoding {
    bool half = false;
    float exposure = 0.0f;
};

// Throws InputError naming the file when it cannot be written.
void write_image(const std::string& path, const Image& image, const ImageMetadata& metadata,
                 const std::vector<ImageLayer>& layers = {}, const ImageEncoding& encoding = {});

// Throws InputError naming `path` unless a file can be written there: its
// folder exists and takes a new file, and the extension names a format. Checked
// before a render starts, so no time is spent on an image that cannot be kept.
void check_can_write(const std::string& path);

// True when the extension's format keeps linear float radiance (and layers).
bool holds_float_radiance(const std::string& path);

// Throws InputError naming the file when it cannot be read.
Image read_image(const std::string& path);

// Every channel of an image, by name, with its wavefront:option:* attributes.
struct ChannelImage {
    uint32_t width = 0, height = 0;
    std::vector<std::string> channel_names;
    std::vector<float> pixels; // interleaved, channel_names.size() per pixel
    ImageOptions options;
};
ChannelImage read_channels(const std::string& path);

// The sRGB transfer function (IEC 61966-2-1) of a linear value, clamped to [0, 1].
float srgb_encode(float linear);
// Its inverse: the linear value of an encoded one in [0, 1].
float srgb_decode(float encoded);

} // namespace wf
