// environment_map.cpp — builds the sampling distribution of
// kernels/lights/environment.h: each texel weighted by its luminance times
// its solid angle, rows chosen by a marginal CDF and texels by per-row CDFs
// (pbrt-v4's PiecewiseConstant2D, but uniform in solid angle within a texel).
// CDFs, not the alias table (host/base/alias_table.h): inverting a CDF is monotone,
// so the sampler's stratified numbers stay stratified over the sphere.
#include "scene/environment_map.h"

#include <cmath>
#include <string>

#include <OpenImageIO/imageio.h>

#include "base/errors.h"
#include "base/input_file.h"

namespace wf {
namespace {

constexpr double kPi = 3.14159265358979323846;

double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

// Fills the cumulative sums of `weights` into cdf[0..n], normalised to end at
// exactly 1; returns the sum.
double fill_cdf(const std::vector<double>& weights, float* cdf) {
    double sum = 0.0;
    for (double w : weights) sum += w;
    double running = 0.0;
    cdf[0] = 0.0f;
    for (size_t i = 0; i < weights.size(); ++i) {
        running += weights[i];
        cdf[i + 1] = sum > 0.0 ? static_cast<float>(running / sum) : static_cast<float>(double(i + 1) / weights.size());
    }
    cdf[weights.size()] = 1.0f;
    return sum;
}

} // namespace

EnvironmentMap make_environment(const Image& image, float scale, float rotate_degrees, const std::string& name) {
    const uint32_t w = image.width, h = image.height;
    if (w == 0 || h == 0) throw InputError(name + ": environment map has no texels");
    if (!std::isfinite(scale) || scale < 0.0f)
        throw InputError(name + ": environment scale " + std::to_string(scale) + " is not a finite non-negative number");
    EnvironmentMap map;
    const double angle = double(rotate_degrees) * kPi / 180.0;
    map.header = Environment{{scale, scale, scale}, 0u, static_cast<float>(std::cos(angle)),
                             static_cast<float>(std::sin(angle)), w, h};
    if (w != 2 * h)
        map.warnings.push_back(name + ": " + std::to_string(w) + "x" + std::to_string(h) +
                               " is not 2:1; used as equirectangular anyway");

    const size_t count = size_t{w} * h;
    map.texels.resize(4 * count);
    size_t negative = 0;
    for (size_t t = 0; t < count; ++t)
        for (int c = 0; c < 3; ++c) {
            const float v = image.rgb[3 * t + c];
            if (!std::isfinite(v))
                throw InputError(name + ": texel (" + std::to_string(t % w) + ", " + std::to_string(t / w) +
                                 ") is " + (std::isnan(v) ? "NaN" : "infinite"));
            if (v < 0.0f) ++negative;
            map.texels[4 * t + c] = v < 0.0f ? 0.0f : v;
        }
    if (negative > 0)
        map.warnings.push_back(name + ": " + std::to_string(negative) + " negative texel values clamped to 0");

    // Texel weight: luminance x solid angle, 2pi/w (cos theta_top - cos theta_bottom).
    std::vector<double> solid_angle(h), weights(w), row_weights(h);
    map.distribution.resize((h + 1) + size_t{h} * (w + 1));
    float* marginal = map.distribution.data();
    double total = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
        solid_angle[y] = 2.0 * kPi / w * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
        for (uint32_t x = 0; x < w; ++x) weights[x] = luminance(&map.texels[4 * (size_t{y} * w + x)]) * solid_angle[y];
        row_weights[y] = fill_cdf(weights, marginal + (h + 1) + size_t{y} * (w + 1));
        total += row_weights[y];
    }
    if (!(total > 0.0)) {
        // Black: sample by solid angle alone, so every direction stays reachable.
        map.warnings.push_back(name + ": environment map is black everywhere");
        for (uint32_t y = 0; y < h; ++y) row_weights[y] = solid_angle[y] * w; // the whole row's
        total = 4.0 * kPi;
    }
    fill_cdf(row_weights, marginal);
    // Density in solid angle, constant over a texel: its probability / its solid angle.
    for (uint32_t y = 0; y < h; ++y) {
        const float* row_cdf = marginal + (h + 1) + size_t{y} * (w + 1);
        for (uint32_t x = 0; x < w; ++x) {
            const double in_row = double(row_cdf[x + 1]) - row_cdf[x];
            const double probability = row_weights[y] / total * in_row;
            map.texels[4 * (size_t{y} * w + x) + 3] = static_cast<float>(probability / solid_angle[y]);
        }
    }
    return map;
}

EnvironmentMap load_environment(const std::string& path, float scale, float rotate_degrees) {
    require_regular_file(path, "environment map");
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        std::string why = OIIO::geterror();
        if (const size_t nl = why.find('\n'); nl != std::string::npos) why.resize(nl);
        throw InputError(path + ": cannot read environment map (" + why + ")");
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels < 3)
        throw InputError(path + ": environment map has " + std::to_string(spec.nchannels) +
                         " channels; it needs RGB");
    const std::string format = in->format_name();
    if (format != "openexr" && format != "hdr" && format != "pfm" && spec.format.basetype != OIIO::TypeDesc::FLOAT &&
        spec.format.basetype != OIIO::TypeDesc::HALF)
        throw InputError(path + ": environment map is " + format + " of " + spec.format.c_str() +
                         ", not linear float radiance (.exr or .hdr)");
    Image image{static_cast<uint32_t>(spec.width), static_cast<uint32_t>(spec.height), {}, {}};
    image.rgb.resize(size_t{image.width} * image.height * 3);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.rgb.data()))
        throw InputError(path + ": cannot read environment map (" + in->geterror() + ")");
    return make_environment(image, scale, rotate_degrees, path);
}

EnvironmentMap constant_environment(float radiance) {
    EnvironmentMap map;
    map.header = Environment{{radiance, radiance, radiance}, WF_ENVIRONMENT_CONSTANT, 1.0f, 0.0f, 1u, 1u};
    map.texels = {1.0f, 1.0f, 1.0f, static_cast<float>(0.25 / kPi)};
    map.distribution = {0.0f, 1.0f, 0.0f, 1.0f};
    return map;
}

void light_unlit_scene(Scene& scene) {
    if (scene.environment || scene.has_punctual_light()) return;
    std::string why;
    if (!scene.has_emissive_triangles()) why = "the scene has no light";
    else if (scene.emits_only_through_textures()) why = "the scene's only light is emission from textures";
    else return;
    scene.environment = std::make_shared<EnvironmentMap>(constant_environment(1.0f));
    scene.warnings.push_back(why + "; lit by a uniform white environment of radiance 1 (--env or --env-uniform L "
                                   "to choose another)");
}

} // namespace wf
