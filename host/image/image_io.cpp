// image_io.cpp — linear radiance goes to float formats unchanged; 8-bit
// formats get the sRGB curve applied here, since OIIO's type conversion alone
// would quantise linear values.
#include "image/image_io.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>


#include <OpenImageIO/imageio.h>

#include "base/errors.h"
#include "base/input_file.h"
#include "base/output_files.h"

namespace wf {

float srgb_encode(float linear) {
    const float x = std::clamp(std::isnan(linear) ? 0.0f : linear, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded) {
    const float x = std::clamp(encoded, 0.0f, 1.0f);
    return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
}

namespace {
// Formats that keep radiance as floats; everything else is display-referred 8-bit.
bool stores_linear_float(const std::string& format) {
    return format == "openexr" || format == "hdr" || format == "tiff";
}

// Whether a file's values are display-encoded (what our 8-bit outputs and
// most PNGs and JPEGs hold): integer pixels, unless the file says linear.
bool holds_srgb(const OIIO::ImageSpec& spec) {
    const std::string space = spec.get_string_attribute("oiio:ColorSpace");
    if (space == "Linear" || space == "linear") return false;
    return !spec.format.is_floating_point();
}
} // namespace

void check_can_write(const std::string& path) {
    if (!OIIO::ImageOutput::create(path))
        throw InputError(path + ": no image format for this extension (" + OIIO::geterror() + ")");
    check_can_write_file(path);
}

bool holds_float_radiance(const std::string& path) {
    auto out = OIIO::ImageOutput::create(path);
    return out && stores_linear_float(out->format_name());
}

Image read_image(const std::string& path) {
    require_regular_file(path, "image");
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError(path + ": cannot read (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels < 3) throw InputError(path + ": has " + std::to_string(spec.nchannels) + " channels, not RGB");
    Image image{static_cast<uint32_t>(spec.width), static_cast<uint32_t>(spec.height), {}, {}};
    image.rgb.resize(size_t{image.width} * image.height * 3);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.rgb.data()))
        throw InputError(path + ": cannot read (" + in->geterror() + ")");
    if (!spec.format.is_floating_point()) {
        image.stored.levels = uint32_t((uint64_t{1} << (8 * spec.format.size())) - 1);
        image.stored.srgb = holds_srgb(spec);
    }
    if (image.stored.srgb)
        for (float& v : image.rgb) v = srgb_decode(v);
    return image;
}

void write_image(const std::string& path, const Image& image, const ImageMetadata& metadata,
                 const std::vector<ImageLayer>& layers, const ImageEncoding& encoding) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw InputError(path + ": no image format for this extension (" + OIIO::geterror() + ")");
    const bool float_format = stores_linear_float(out->format_name());
    if (!layers.empty() && !float_format)
        throw InputError(path + ": image layers need a float format such as .exr");
    int channels = 3;
    for (const ImageLayer& l : layers) channels += static_cast<int>(l.channels.size());
    const OIIO::TypeDesc stored = !float_format ? OIIO::TypeDesc::UINT8
                                  : encoding.half ? OIIO::TypeDesc::HALF
                                                  : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), channels, stored);
    spec.channelnames = {"R", "G", "B"};
    for (const ImageLayer& l : layers)
        for (const std::string& c : l.channels) spec.channelnames.push_back(l.name + "." + c);
    spec.attribute("oiio:ColorSpace", float_format ? "Linear" : "sRGB");
    spec.attribute("Software", "wavefront " WF_VERSION);
    // Numbers as numbers where the format keeps them (EXR); 8-bit writers (PNG
    // text chunks, JPEG comments) keep strings alone and drop the rest.
    auto number = [&](const char* name, auto value) {
        if (float_format) spec.attribute(name, value);
        else spec.attribute(name, std::to_string(value));
    };
    number("wavefront:samplesPerPixel", static_cast<int>(metadata.samples_per_pixel));
    number("wavefront:renderTimeSeconds", static_cast<float>(metadata.render_seconds));
    spec.attribute("wavefront:device", metadata.device);
    number("wavefront:seed", static_cast<int>(metadata.seed));
    spec.attribute("wavefront:scene", metadata.scene);
    number("wavefront:interrupted", metadata.interrupted ? 1 : 0);
    for (const auto& [name, value] : metadata.options) spec.attribute("wavefront:option:" + name, value);

    // Interleaved: RGB, then each layer's channels, pixel by pixel.
    const size_t count = size_t{image.width} * image.height;
    std::vector<float> pixels(count * channels);
    for (size_t p = 0; p < count; ++p) {
        float* out_pixel = &pixels[p * channels];
        out_pixel = std::copy_n(&image.rgb[3 * p], 3, out_pixel);
        for (const ImageLayer& l : layers) out_pixel = std::copy_n(&l.image.rgb[3 * p], l.channels.size(), out_pixel);
    }
    if (!float_format) {
        const float scale = std::exp2(encoding.exposure);
        for (float& v : pixels) v = srgb_encode(v * scale);
    }
    const std::filesystem::path temporary = temporary_beside(path);
    bool written = out->open(temporary.string(), spec);
    written = written && out->write_image(OIIO::TypeDesc::FLOAT, pixels.data());
    written = out->close() && written;
    if (!written) {
        std::error_code ignored; // a failed open may still have created it
        std::filesystem::remove(temporary, ignored);
        throw InputError(path + ": write failed (" + out->geterror() + ")");
    }
    replace_with(temporary, path);
}

ChannelImage read_channels(const std::string& path) {
    require_regular_file(path, "image");
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError(path + ": cannot read (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec& spec = in->spec();
    ChannelImage image;
    image.width = static_cast<uint32_t>(spec.width);
    image.height = static_cast<uint32_t>(spec.height);
    image.channel_names = spec.channelnames;
    image.pixels.resize(size_t{image.width} * image.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw InputError(path + ": cannot read (" + in->geterror() + ")");
    const std::string prefix = "wavefront:option:";
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        if (p.name().string().rfind(prefix, 0) == 0)
            image.options.emplace_back(p.name().string().substr(prefix.size()), p.get_string());
    return image;
}

} // namespace wf
