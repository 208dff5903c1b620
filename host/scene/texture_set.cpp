// texture_set.cpp — decoding with OpenImageIO from memory, and packing.
//
// Why OpenImageIO from memory and not tinygltf's stb decode: the glTF loader
// has tinygltf keep each image's encoded bytes (from a file, a data URI or a
// bufferView alike), so there is one decoder for all three, the one the rest
// of the program already uses for image files, and its errors are reported
// with the image and the material that uses it rather than failing the parse.
// OpenImageIO 2.4 reads PNG and JPEG through Filesystem::IOMemReader.
#include "scene/texture_set.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "base/errors.h"

namespace wf {
namespace {

// A file name whose extension makes OpenImageIO pick the right reader: the
// signature for PNG and JPEG, else the name it came with.
std::string format_name(const unsigned char* bytes, size_t size, const std::string& name) {
    static const unsigned char png[] = {0x89, 'P', 'N', 'G'};
    static const unsigned char jpeg[] = {0xff, 0xd8, 0xff};
    if (size >= sizeof png && std::memcmp(bytes, png, sizeof png) == 0) return "image.png";
    if (size >= sizeof jpeg && std::memcmp(bytes, jpeg, sizeof jpeg) == 0) return "image.jpg";
    return name.empty() ? "image.png" : name;
}

std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text.size() > 200 ? text.substr(0, 200) + "..." : text;
}

} // namespace

DecodedImage decode_image(const unsigned char* bytes, size_t size, const std::string& name,
                          const std::string& where) {
    if (size == 0) throw InputError(where + ": empty image");
    OIIO::Filesystem::IOMemReader reader(bytes, size);
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1); // glTF alpha is straight, not premultiplied
    // OpenImageIO 2.4's readers take the proxy from the configuration too;
    // without this attribute they try to open the file name.
    OIIO::Filesystem::IOProxy* proxy = &reader;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto input = OIIO::ImageInput::open(format_name(bytes, size, name), &config, &reader);
    if (!input) throw InputError(where + ": cannot decode: " + one_line(OIIO::geterror()));
    const OIIO::ImageSpec& spec = input->spec();
    const auto width = uint64_t(spec.width), height = uint64_t(spec.height);
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
        throw InputError(where + ": not a 2D image (" + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + ", " + std::to_string(spec.nchannels) + " channels)");
    if (width * height > (uint64_t(1) << 28)) // 16384² texels, 1 GiB
        throw InputError(where + ": " + std::to_string(width) + "x" + std::to_string(height) +
                         " is larger than 16384x16384 texels");
    const int channels = std::min(spec.nchannels, 4);
    std::vector<unsigned char> pixels(size_t(width * height) * size_t(channels));
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data()))
        throw InputError(where + ": cannot decode: " + one_line(input->geterror()));

    DecodedImage image;
    image.width = uint32_t(width);
    image.height = uint32_t(height);
    image.channels = uint32_t(spec.nchannels);
    image.texels.resize(size_t(width * height));
    for (size_t i = 0; i < image.texels.size(); ++i) {
        const unsigned char* p = &pixels[i * size_t(channels)];
        switch (channels) {
        case 1: image.texels[i] = pack_rgba8(p[0], p[0], p[0], 255); break;
        case 2: image.texels[i] = pack_rgba8(p[0], p[0], p[0], p[1]); break;
        case 3: image.texels[i] = pack_rgba8(p[0], p[1], p[2], 255); break;
        default: image.texels[i] = pack_rgba8(p[0], p[1], p[2], p[3]); break;
        }
    }
    return image;
}

uint32_t TextureSet::add_texels(const DecodedImage& image, const std::string& where) {
    if (image.texels.size() > std::numeric_limits<uint32_t>::max() - texels.size())
        throw InputError(where + ": the scene's textures pass 2^32 texels");
    const auto offset = uint32_t(texels.size());
    texels.insert(texels.end(), image.texels.begin(), image.texels.end());
    return offset;
}

int32_t TextureSet::add_info(const TextureInfo& info, const std::string& name) {
    infos.push_back(info);
    infos.back().stride = 1;
    names.push_back(name);
    return int32_t(infos.size() - 1);
}

TextureRef no_texture() {
    TextureRef ref{};
    ref.texture = -1;
    ref.texcoord = 0;
    const std::array<float, 6> identity = texture_transform(0, 0, 0, 1, 1);
    std::copy(identity.begin(), identity.end(), ref.transform);
    return ref;
}

std::array<TextureRef, WF_TEXTURE_SLOTS> no_textures() {
    std::array<TextureRef, WF_TEXTURE_SLOTS> slots;
    slots.fill(no_texture());
    return slots;
}

std::array<float, 6> texture_transform(float offset_u, float offset_v, float rotation, float scale_u,
                                       float scale_v) {
    const float c = std::cos(rotation), s = std::sin(rotation);
    // [1 0 ou; 0 1 ov] [c s; -s c] [su 0; 0 sv], row-major 2x3. The rotation is
    // what the sample model TextureTransformTest, Babylon.js and three.js do; the
    // extension's GLSL listing, read column-major, turns the other way, a known
    // erratum (KhronosGroup/glTF issue 1563).
    return {c * scale_u, s * scale_v, offset_u, -s * scale_u, c * scale_v, offset_v};
}

} // namespace wf
