// bsdf_kind_choice.cpp — which BSDF kind shades a material.
#include "device/bsdf_kind_choice.h"

namespace wf {

uint32_t bsdf_kind_of(const SceneMaterial& m) {
    const bool sheen = m.sheen_color.r > 0.0f || m.sheen_color.g > 0.0f || m.sheen_color.b > 0.0f;
    if (m.transmission > 0.0f || m.clearcoat > 0.0f || sheen) return WF_BSDF_GENERAL;
    return WF_BSDF_OPAQUE;
}

} // namespace wf
