// bsdf_kind_choice.cpp — which BSDF kind shades a material.
#include "device/bsdf_kind_choice.h"

namespace wf {

bool has_specular(const SceneMaterial& m) { return m.metallic > 0.0f || m.specular > 0.0f || has_transmission(m); }

bool has_transmission(const SceneMaterial& m) { return m.transmission > 0.0f; }

bool has_clearcoat(const SceneMaterial& m) { return m.clearcoat > 0.0f; }

bool has_sheen(const SceneMaterial& m) {
    return m.sheen_color.r > 0.0f || m.sheen_color.g > 0.0f || m.sheen_color.b > 0.0f;
}

uint32_t bsdf_kind_of(const SceneMaterial&) { return WF_BSDF_LAYERED; }

} // namespace wf
