// scene_features.cpp — what a scene uses, from its materials and lights.
#include "device/scene_features.h"

#include <utility>
#include <vector>

#include "device/bsdf_kind_choice.h"
#include "scene/environment_map.h"

namespace wf {
namespace {

// Each feature with its define's name and its name in the report.
std::vector<std::pair<bool, std::pair<const char*, const char*>>> listed(const SceneFeatures& f) {
#define WF_BSDF_KIND_FEATURE(kind, name, what) {f.bsdf_kinds[WF_BSDF_##kind], {"WF_HAS_BSDF_" #kind, name " BSDF"}},
    return {WF_BSDF_KINDS(WF_BSDF_KIND_FEATURE) // the kinds first: every scene has one
            {f.textures, {"WF_HAS_TEXTURES", "textures"}},
            {f.normal_maps, {"WF_HAS_NORMAL_MAPS", "normal maps"}},
            {f.alpha_mask, {"WF_HAS_ALPHA_MASK", "alpha mask"}},
            {f.vertex_colors, {"WF_HAS_VERTEX_COLORS", "vertex colours"}},
            {f.emissive_triangles, {"WF_HAS_EMISSIVE_TRIANGLES", "emissive triangles"}},
            {f.punctual_lights, {"WF_HAS_PUNCTUAL_LIGHTS", "punctual lights"}},
            {f.environment, {"WF_HAS_ENVIRONMENT", "environment"}},
            {f.specular, {"WF_HAS_SPECULAR", "specular"}},
            {f.transmission, {"WF_HAS_TRANSMISSION", "transmission"}},
            {f.clearcoat, {"WF_HAS_CLEARCOAT", "clear coat"}},
            {f.sheen, {"WF_HAS_SHEEN", "sheen"}},
            {f.instances, {"WF_HAS_INSTANCES", "instances"}}};
#undef WF_BSDF_KIND_FEATURE
}

} // namespace

SceneFeatures scene_features(const Scene& scene) {
    SceneFeatures f;
    f.textures = f.normal_maps = f.alpha_mask = f.specular = f.transmission = f.clearcoat = f.sheen = false;
    f.bsdf_kinds.fill(false);
    for (const SceneMaterial& m : scene.materials) {
        f.bsdf_kinds[bsdf_kind_of(m)] = true;
        for (const TextureRef& ref : m.textures) f.textures = f.textures || ref.texture >= 0;
        f.normal_maps = f.normal_maps || m.textures[WF_TEXTURE_NORMAL].texture >= 0;
        f.alpha_mask = f.alpha_mask || m.alpha_mode == WF_ALPHA_MASK;
        f.specular = f.specular || has_specular(m);
        f.transmission = f.transmission || has_transmission(m);
        f.clearcoat = f.clearcoat || has_clearcoat(m);
        f.sheen = f.sheen || has_sheen(m);
    }
    f.vertex_colors = scene.has_vertex_colors();
    f.emissive_triangles = scene.has_emissive_triangles();
    f.punctual_lights = !scene.punctual_lights.empty();
    f.environment = scene.environment != nullptr;
    return f;
}

std::string feature_defines(const SceneFeatures& features) {
    std::string options;
    for (const auto& [on, names] : listed(features))
        options += std::string(options.empty() ? "" : " ") + "-D" + names.first + "=" + (on ? "1" : "0");
    return options;
}

std::string describe_features(const SceneFeatures& features) {
    std::string text;
    for (const auto& [on, names] : listed(features))
        if (on) text += (text.empty() ? "" : ", ") + std::string(names.second);
    return text.empty() ? "none" : text;
}

} // namespace wf
