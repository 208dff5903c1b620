// image_writer.cpp — linear radiance goes to float formats unchanged; 8-bit
// formats get the sRGB curve applied here, since OIIO's type conversion alone
// would quantise linear values.
#include "image_writer.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <OpenImageIO/imageio.h>

#include "errors.h"

namespace wf {

float srgb_encode(float linear) {
    const float x = std::clamp(std::isnan(linear) ? 0.0f : linear, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

namespace {
// Formats that keep radiance as floats; everything else is display-referred 8-bit.
bool stores_linear_float(const std::string& format) {
    return format == "openexr" || format == "hdr" || format == "pfm" || format == "tiff";
}
} // namespace

void write_image(const std::string& path, const Image& image, const ImageMetadata& metadata) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw InputError(path + ": no image format for this extension (" + OIIO::geterror() + ")");
    const bool float_format = stores_linear_float(out->format_name());
    OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), 3,
                         float_format ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", float_format ? "Linear" : "sRGB");
    spec.attribute("Software", "wavefront " WF_VERSION);
    spec.attribute("wavefront:samplesPerPixel", static_cast<int>(metadata.samples_per_pixel));
    spec.attribute("wavefront:renderTimeSeconds", static_cast<float>(metadata.render_seconds));
    spec.attribute("wavefront:device", metadata.device);
    spec.attribute("wavefront:seed", static_cast<int>(metadata.seed));
    spec.attribute("wavefront:scene", metadata.scene);

    std::vector<float> pixels = image.rgb;
    if (!float_format)
        for (float& v : pixels) v = srgb_encode(v);
    if (!out->open(path, spec)) throw InputError(path + ": cannot write (" + out->geterror() + ")");
    const bool written = out->write_image(OIIO::TypeDesc::FLOAT, pixels.data());
    const bool closed = out->close();
    if (!written || !closed) throw InputError(path + ": write failed (" + out->geterror() + ")");
}

} // namespace wf
