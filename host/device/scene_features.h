// scene_features.h — the coarse features a scene uses, which decide what the
// kernels are compiled with (issue 6: leave out what a scene does not need).
// Each is a -D define of the program: code for an absent feature is not
// compiled, and what it would have returned (a texture of 1, an unbent
// normal, a hit that passes, a light kind never chosen, an interface that
// reflects nothing) is exactly what the generic program computes for such a
// scene, or (the last, for a black base) differs only where a zero BSDF
// value ends the path either way, so the images are bit-identical.
// Kept coarse on purpose: a handful of switches, not a define per parameter.
#pragma once

#include <array>
#include <string>

#include "scene/scene.h"
#include "wavefront/bsdf_kinds.h"

namespace wf {

struct SceneFeatures {
    bool textures = true;           // any material reads a texture
    bool normal_maps = true;        // any material has a normal map
    bool alpha_mask = true;         // any material is alpha-masked
    bool vertex_colors = true;      // any COLOR_0 that is not white
    bool emissive_triangles = true; // any triangle emits
    bool punctual_lights = true;    // KHR_lights_punctual
    bool environment = true;        // an environment light
    bool specular = true;           // any material reflects at its interface: a metal, a specular layer, or it transmits
    bool transmission = true;       // any material transmits (KHR_materials_transmission)
    bool clearcoat = true;          // any material has a clear coat (KHR_materials_clearcoat)
    bool sheen = true;              // any material has a sheen (KHR_materials_sheen)
    // Shared meshes placed by instances: a two-level BVH (host/bvh/instance_bvh.h).
    // Not a choice but the layout of the scene's buffers, so set from the
    // scene even where every other feature is on (build_render_program).
    bool instances = false;
    // Which BSDF kinds its materials have (host/device/bsdf_kind_choice.h), by WF_BSDF_*.
    std::array<bool, WF_BSDF_KIND_COUNT> bsdf_kinds = filled(true);

    // Every feature on: the generic program, for --no-specialize.
    static SceneFeatures all() { return SceneFeatures{}; }

private:
    static std::array<bool, WF_BSDF_KIND_COUNT> filled(bool on) {
        std::array<bool, WF_BSDF_KIND_COUNT> a;
        a.fill(on);
        return a;
    }
};

SceneFeatures scene_features(const Scene& scene);

// The program's build options: -DWF_HAS_<FEATURE>=0|1 for each, and
// -DWF_HAS_BSDF_<KIND>=0|1 for each BSDF kind.
std::string feature_defines(const SceneFeatures& features);

// "textures, normal maps, ..." or "none".
std::string describe_features(const SceneFeatures& features);

} // namespace wf
