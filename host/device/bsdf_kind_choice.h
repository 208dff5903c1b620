// bsdf_kind_choice.h — which BSDF kind (include/wavefront/bsdf_kinds.h) shades a
// material: the narrowest whose lobes cover every value its factors and
// textures can take. A texture only scales its factor, so a factor of 0 rules
// its lobe out at every point.
#pragma once

#include <cstdint>

#include "scene/scene.h"
#include "wavefront/bsdf_kinds.h"

namespace wf {

uint32_t bsdf_kind_of(const SceneMaterial& m);

// Whether the material has the lobe at all (its factor above 0). Its
// interface reflects where it is a metal, its dielectric layer has a
// specular factor, or it transmits (through that interface).
bool has_specular(const SceneMaterial& m);
bool has_transmission(const SceneMaterial& m);
bool has_clearcoat(const SceneMaterial& m);
bool has_sheen(const SceneMaterial& m);

} // namespace wf
