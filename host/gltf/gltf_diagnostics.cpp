// gltf_diagnostics.cpp — see gltf_diagnostics.h.
#include "gltf/gltf_diagnostics.h"

#include <set>

#include "base/errors.h"

namespace wf {
namespace {

const std::set<std::string>& supported_extensions() {
    static const std::set<std::string> names = {
        "EXT_mesh_gpu_instancing", "KHR_lights_punctual",        "KHR_materials_clearcoat",
        "KHR_materials_emissive_strength", "KHR_materials_ior",  "KHR_materials_specular",
        "KHR_materials_transmission",      "KHR_materials_sheen", "KHR_materials_volume",
        "KHR_texture_transform"};
    return names;
}

} // namespace

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw InputError(where + ": " + what);
}

std::string label(const char* kind, size_t index, const std::string& name) {
    return name.empty() ? std::string(kind) + " " + std::to_string(index)
                        : std::string(kind) + " '" + name + "'";
}

std::string one_line(const std::string& text) {
    constexpr size_t kMaxLength = 200;
    std::string line;
    for (char c : text) {
        const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
        if (!space)
            line += c;
        else if (!line.empty() && line.back() != ' ')
            line += ' ';
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (line.size() > kMaxLength) line = line.substr(0, kMaxLength) + "...";
    return line;
}

std::string indexed_label(const char* kind, size_t index, const std::string& name) {
    return std::string(kind) + " " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

void check_extensions(const tinygltf::Model& model, const std::string& path,
                      std::vector<std::string>& warnings) {
    for (const std::string& name : model.extensionsRequired)
        if (!supported_extensions().count(name))
            fail(path, "required extension " + name + " is not supported");
    std::string ignored;
    for (const std::string& name : model.extensionsUsed)
        if (!supported_extensions().count(name)) ignored += (ignored.empty() ? "" : ", ") + name;
    if (!ignored.empty()) warnings.push_back("extensions not supported, ignored: " + ignored);
}

void check_core_features(const tinygltf::Model& model, std::vector<std::string>& warnings) {
    if (!model.skins.empty())
        warnings.push_back(std::to_string(model.skins.size()) + " skin(s) not supported, rendered in the bind pose");
    size_t morphed = 0;
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& primitive : mesh.primitives) morphed += !primitive.targets.empty();
    if (morphed)
        warnings.push_back("morph targets not supported on " + std::to_string(morphed) +
                           " primitive(s), rendered without them");
    if (!model.animations.empty())
        warnings.push_back(std::to_string(model.animations.size()) +
                           " animation(s) not supported, rendered at rest");
}

} // namespace wf
