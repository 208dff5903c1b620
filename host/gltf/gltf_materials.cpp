// gltf_materials.cpp — see gltf_materials.h.
#include "gltf/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gltf/gltf_diagnostics.h"
#include "gltf/gltf_float.h"

namespace wf {
namespace {

// tinygltf fills defaults but does not check every array's length.
double element_or(const std::vector<double>& values, size_t i, double fallback) {
    return i < values.size() ? values[i] : fallback;
}

// A number from a material extension's object, or `fallback` where the
// extension or the property is absent.
double extension_number(const tinygltf::Material& material, const char* extension_name,
                        const char* property, double fallback) {
    const auto extension = material.extensions.find(extension_name);
    if (extension == material.extensions.end() || !extension->second.Has(property)) return fallback;
    const tinygltf::Value& value = extension->second.Get(property);
    return value.IsNumber() ? value.GetNumberAsDouble() : fallback;
}

// An RGB factor of a material extension, or white where it is absent.
// KHR_materials_specular's colour may exceed 1; it must be finite and not negative.
glm::vec3 extension_color(const tinygltf::Material& material, const char* extension_name, const char* property,
                          const std::string& where) {
    const auto extension = material.extensions.find(extension_name);
    if (extension == material.extensions.end() || !extension->second.Has(property)) return glm::vec3(1.0f);
    const tinygltf::Value& value = extension->second.Get(property);
    const std::string what = std::string(extension_name) + "." + property;
    if (!value.IsArray() || value.ArrayLen() != 3) fail(where, what + " must have 3 numbers");
    glm::vec3 color;
    for (int c = 0; c < 3; ++c) {
        const tinygltf::Value& number = value.Get(c);
        const double x = number.IsNumber() ? number.GetNumberAsDouble() : -1.0;
        if (!(x >= 0.0)) fail(where, what + " must hold numbers >= 0");
        color[c] = to_float(x, where, what);
    }
    return color;
}

// A factor that glTF defines on [0, 1]: NaN is an error, the rest is clamped.
float unit_factor(double value, const std::string& where, const char* what) {
    if (std::isnan(value)) fail(where, std::string(what) + " is NaN");
    return float(std::clamp(value, 0.0, 1.0));
}

} // namespace

SceneMaterial convert_material(const tinygltf::Material& material, size_t index,
                               const std::string& path) {
    const std::string where = path + ": " + label("material", index, material.name);
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    SceneMaterial converted;
    converted.name = material.name;
    converted.double_sided = material.doubleSided;
    converted.metallic = unit_factor(pbr.metallicFactor, where, "metallicFactor");
    converted.roughness = unit_factor(pbr.roughnessFactor, where, "roughnessFactor");
    converted.transmission = unit_factor(
        extension_number(material, "KHR_materials_transmission", "transmissionFactor", 0.0), where,
        "transmissionFactor");
    converted.specular = unit_factor(
        extension_number(material, "KHR_materials_specular", "specularFactor", 1.0), where, "specularFactor");
    converted.specular_color = extension_color(material, "KHR_materials_specular", "specularColorFactor", where);
    // sheenColorFactor defaults to black (no sheen); read as a colour, then kept to [0, 1].
    if (material.extensions.count("KHR_materials_sheen") &&
        material.extensions.at("KHR_materials_sheen").Has("sheenColorFactor"))
        converted.sheen_color =
            glm::min(extension_color(material, "KHR_materials_sheen", "sheenColorFactor", where), glm::vec3(1.0f));
    // Without KHR_materials_volume, or with its thickness 0, glTF's
    // transmission is through a thin wall (KHR_materials_volume, "Thin-walled").
    const double thickness = extension_number(material, "KHR_materials_volume", "thicknessFactor", 0.0);
    if (!(thickness >= 0.0 && std::isfinite(thickness)))
        fail(where, "KHR_materials_volume.thicknessFactor must be finite and >= 0");
    converted.thin_walled = thickness == 0.0;
    converted.clearcoat = unit_factor(extension_number(material, "KHR_materials_clearcoat", "clearcoatFactor", 0.0),
                                      where, "clearcoatFactor");
    converted.clearcoat_roughness =
        unit_factor(extension_number(material, "KHR_materials_clearcoat", "clearcoatRoughnessFactor", 0.0), where,
                    "clearcoatRoughnessFactor");
    converted.sheen_roughness = unit_factor(
        extension_number(material, "KHR_materials_sheen", "sheenRoughnessFactor", 0.0), where, "sheenRoughnessFactor");
    // KHR_materials_ior allows 0 as "a perfect absorber"; that, and anything below 1, is not supported.
    const double ior = extension_number(material, "KHR_materials_ior", "ior", 1.5);
    if (!(ior >= 1.0 && ior < 1e3)) fail(where, "ior " + std::to_string(ior) + " is not in [1, 1000)");
    converted.ior = float(ior);
    const double strength = extension_number(material, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
    for (int c = 0; c < 3; ++c) {
        converted.base_color[c] = unit_factor(element_or(pbr.baseColorFactor, size_t(c), 1.0), where,
                                              "baseColorFactor");
        const double emission = element_or(material.emissiveFactor, size_t(c), 0.0) * strength;
        if (emission < 0.0) fail(where, "emission must be non-negative");
        converted.emission[c] = to_float(emission, where, "emissiveFactor x emissiveStrength");
    }
    return converted;
}

std::vector<std::string> unsupported_properties(const tinygltf::Material& material) {
    // Properties of supported extensions that are read nowhere; a colour
    // factor at its default, white, changes nothing and is not one of them.
    struct Property {
        const char* extension;
        const char* name;
        bool colour_factor;
    };
    static const Property kIgnored[] = {{"KHR_materials_volume", "attenuationColor", true},
                                        {"KHR_materials_volume", "attenuationDistance", false},
                                        {"KHR_materials_clearcoat", "clearcoatNormalTexture", false}};
    const auto is_white = [](const tinygltf::Value& value) {
        if (!value.IsArray() || value.ArrayLen() != 3) return false;
        for (int c = 0; c < 3; ++c)
            if (!value.Get(c).IsNumber() || value.Get(c).GetNumberAsDouble() != 1.0) return false;
        return true;
    };
    std::vector<std::string> found;
    for (const Property& p : kIgnored) {
        const auto extension = material.extensions.find(p.extension);
        if (extension == material.extensions.end() || !extension->second.Has(p.name)) continue;
        if (p.colour_factor && is_white(extension->second.Get(p.name))) continue;
        found.push_back(std::string(p.extension) + "." + p.name);
    }
    return found;
}

SceneMaterial default_material() {
    SceneMaterial material;
    material.name = "default";
    material.base_color = glm::vec3(1.0f);
    material.metallic = 1.0f;
    material.roughness = 1.0f;
    material.specular = 1.0f;
    return material;
}

} // namespace wf
