// image_options.cpp — each value as text: as its flag gives it, or "none",
// "first" or "the camera's" for a flag not given.
#include "session/image_options.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "base/file_fingerprint.h"

namespace wf {
namespace {

std::string look_at_text(const std::array<float, 9>& v) {
    std::string text;
    for (float x : v) text += (text.empty() ? "" : ",") + std::to_string(x);
    return text;
}

// Adaptive sampling stops pixels apart, so its target shapes the image.
std::string adaptive_text(const ProgressOptions& p) {
    if (!p.adaptive) return "off";
    std::ostringstream text;
    text << "target-error " << p.target_relmse;
    return text.str();
}

} // namespace

std::string canonical_path(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : canonical.string();
}

std::string aov_names(const RenderSettings& s) {
    std::string names;
    for (const auto& [name, bit] : kAovBits)
        if (s.aovs & bit) names += (names.empty() ? "" : ",") + std::string(name);
    if (s.bounce_layers) names += names.empty() ? "bounces" : ",bounces";
    return names.empty() ? "none" : names;
}

ImageOptions image_options(const RenderOptions& o, ImageSize size) {
    const RenderSettings& s = o.settings;
    return {{"scene", canonical_path(o.scene)},
            {"scene-contents", file_fingerprint(o.scene)},
            {"size", std::to_string(size.width) + "x" + std::to_string(size.height)},
            {"camera", o.look_at ? "look-at" : o.camera < 0 ? "first" : std::to_string(o.camera)},
            {"look-at", o.look_at ? look_at_text(*o.look_at) : "none"},
            {"fov", o.fov ? std::to_string(*o.fov) : "the camera's"},
            {"instancing", kInstancingNames[static_cast<size_t>(o.instancing)]},
            {"seed", std::to_string(s.seed)},
            {"max-depth", s.max_depth == WF_UNLIMITED_DEPTH ? "unlimited" : std::to_string(s.max_depth)},
            {"light-sampling", choice_name(kLightSamplingNames, s.light_sampling)},
            {"hemisphere", choice_name(kHemisphereNames, s.hemisphere)},
            {"sampler", choice_name(kSamplerNames, s.sampler)},
            {"env", o.environment.empty() ? "none" : o.environment},
            {"env-rotate", std::to_string(o.environment_rotate)},
            {"env-scale", std::to_string(o.environment_scale)},
            {"env-uniform", o.environment_uniform ? std::to_string(*o.environment_uniform) : "none"},
            {"aov", aov_names(s)},
            {"adaptive", adaptive_text(o.progress)},
            {"version", WF_VERSION}};
}

ImageOptions with_denoiser(ImageOptions options) {
    options.push_back({"denoise", "Open Image Denoise 2.x, RT filter, hdr, prefiltered albedo and normal"});
    return options;
}

ImageOptions resume_checks(ImageOptions options) {
    options.erase(std::remove_if(options.begin(), options.end(), [](const auto& o) { return o.first == "scene"; }),
                  options.end());
    return options;
}

} // namespace wf
