// gltf_lights.cpp — see gltf_lights.h. This tinygltf keeps a node's light
// index only in node.extensions["KHR_lights_punctual"].light.
#include "gltf/gltf_lights.h"

#include <cmath>

#include "base/errors.h"
#include "gltf/gltf_diagnostics.h"
#include "gltf/gltf_float.h"

namespace wf {
namespace {

void store3(float* out, const glm::dvec3& v) {
    for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(v[k]);
}

} // namespace

std::vector<PunctualLight> punctual_lights(const tinygltf::Model& model, const std::vector<NodeWorld>& nodes,
                                           const std::string& path) {
    std::vector<PunctualLight> lights;
    for (const NodeWorld& nw : nodes) {
        const tinygltf::Node& node = model.nodes.at(nw.node);
        const auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext == node.extensions.end() || !ext->second.Has("light")) continue;
        const std::string where = path + ": " + indexed_label("node", nw.node, node.name);
        const tinygltf::Value& index_value = ext->second.Get("light");
        const int index = index_value.IsNumber() ? index_value.GetNumberAsInt() : -1;
        if (index < 0 || size_t(index) >= model.lights.size())
            throw InputError(where + ": KHR_lights_punctual light " + std::to_string(index) + " does not exist");
        const tinygltf::Light& l = model.lights[size_t(index)];
        const std::string what = where + ": " + indexed_label("light", size_t(index), l.name);

        glm::dvec3 color(1.0);
        if (!l.color.empty()) {
            if (l.color.size() != 3) throw InputError(what + ": color needs three numbers");
            color = glm::dvec3(l.color[0], l.color[1], l.color[2]);
        }
        const glm::dvec3 intensity = color * l.intensity;
        for (int k = 0; k < 3; ++k)
            if (intensity[k] < 0.0) throw InputError(what + ": color x intensity must be non-negative");

        PunctualLight p{};
        if (l.type == "point") p.type = WF_PUNCTUAL_POINT;
        else if (l.type == "spot") p.type = WF_PUNCTUAL_SPOT;
        else if (l.type == "directional") p.type = WF_PUNCTUAL_DIRECTIONAL;
        else throw InputError(what + ": unknown light type '" + l.type + "'");

        const glm::dvec3 axis(nw.world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
        if (!(glm::length(axis) > 0.0) || !std::isfinite(glm::length(axis)))
            throw InputError(where + ": its transform collapses the light's direction");
        store3(p.position, glm::dvec3(nw.world[3]));
        store3(p.direction, glm::normalize(axis));
        for (int k = 0; k < 3; ++k) p.intensity[k] = to_float(intensity[k], what, "color x intensity");
        p.range = to_float(l.range, what, "range");
        p.cos_inner = 1.0f;
        p.cos_outer = -1.0f;
        if (p.type == WF_PUNCTUAL_SPOT) {
            const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
            if (!(inner >= 0.0 && inner < outer && outer <= 0.5 * 3.14159265358979323846 + 1e-9))
                throw InputError(what + ": spot cone angles need 0 <= inner < outer <= pi/2");
            p.cos_inner = static_cast<float>(std::cos(inner));
            p.cos_outer = static_cast<float>(std::cos(outer));
        }
        lights.push_back(p);
    }
    return lights;
}

} // namespace wf
