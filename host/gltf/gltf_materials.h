// gltf_materials.h — a glTF material's factors into a SceneMaterial:
// metallic-roughness with KHR_materials_transmission, _ior, _specular and
// _emissive_strength (its textures are gltf_textures.h's). A factor glTF
// defines on [0, 1] is clamped to it; NaN, an ior outside [1, 1000) and a
// negative or non-finite emission are InputErrors naming the material.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace wf {

SceneMaterial convert_material(const tinygltf::Material& material, size_t index, const std::string& path);

// The properties of the extensions above that the renderer does not read
// and that the material sets (e.g. "KHR_materials_specular.specularTexture"):
// the loader warns about each once.
std::vector<std::string> unsupported_properties(const tinygltf::Material& material);

// glTF's defaults for a primitive without a material: white, metallic 1,
// roughness 1 (glTF 2.0, section 3.9.6), not emissive.
SceneMaterial default_material();

} // namespace wf
