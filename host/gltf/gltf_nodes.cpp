// gltf_nodes.cpp — see gltf_nodes.h.
#include "gltf/gltf_nodes.h"

#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gltf/gltf_accessors.h"
#include "scene/mesh_placement.h"
#include "gltf/gltf_diagnostics.h"
#include "gltf/gltf_float.h"

namespace wf {

namespace {

// Translation, then rotation (a quaternion x, y, z, w, as glTF stores it, made
// unit here), then scale: glTF's T R S.
glm::dmat4 trs_matrix(const glm::dvec3& translation, const glm::dvec4& rotation, const glm::dvec3& scale) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), translation);
    m *= glm::mat4_cast(glm::normalize(glm::dquat(rotation.w, rotation.x, rotation.y, rotation.z))); // glm takes w first
    return glm::scale(m, scale);
}

} // namespace

glm::dmat4 local_transform(const tinygltf::Node& node, const std::string& where) {
    glm::dmat4 transform(1.0);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) fail(where, "matrix must have 16 numbers");
        transform = glm::make_mat4(node.matrix.data()); // both column-major
    } else {
        if (!node.translation.empty() && node.translation.size() != 3)
            fail(where, "translation must have 3 numbers");
        if (!node.rotation.empty() && node.rotation.size() != 4)
            fail(where, "rotation must have 4 numbers");
        if (!node.scale.empty() && node.scale.size() != 3) fail(where, "scale must have 3 numbers");
        transform = trs_matrix(node.translation.empty() ? glm::dvec3(0.0) : glm::make_vec3(node.translation.data()),
                               node.rotation.empty() ? glm::dvec4(0, 0, 0, 1) : glm::make_vec4(node.rotation.data()),
                               node.scale.empty() ? glm::dvec3(1.0) : glm::make_vec3(node.scale.data()));
    }
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            if (!std::isfinite(transform[column][row])) fail(where, "transform is not finite");
    return transform;
}

std::vector<glm::dmat4> mesh_instances(const tinygltf::Model& model, const tinygltf::Node& node,
                                       const std::string& where) {
    const auto extension = node.extensions.find("EXT_mesh_gpu_instancing");
    if (extension == node.extensions.end()) return {};
    const std::string at = where + ": EXT_mesh_gpu_instancing";
    const tinygltf::Value& attributes = extension->second.Get("attributes");
    if (!attributes.IsObject()) fail(at, "has no attributes");
    const auto accessor_of = [&](const char* name) {
        if (!attributes.Has(name)) return -1;
        const tinygltf::Value& v = attributes.Get(name);
        if (!v.IsInt() || v.GetNumberAsInt() < 0) fail(at, std::string(name) + " must be an accessor index");
        return v.GetNumberAsInt();
    };
    const int translation = accessor_of("TRANSLATION"), rotation = accessor_of("ROTATION"),
              scale = accessor_of("SCALE");
    std::vector<glm::vec3> translations, scales;
    if (translation >= 0) translations = read_vec3_attribute(model, translation, at, "TRANSLATION");
    if (scale >= 0) scales = read_vec3_attribute(model, scale, at, "SCALE");
    const size_t count = translation >= 0 ? translations.size()
                         : scale >= 0     ? scales.size()
                         : rotation >= 0  ? find_accessor(model, rotation, at, "ROTATION").count
                                          : 0;
    if (count == 0) fail(at, "names none of TRANSLATION, ROTATION and SCALE");
    if ((translation >= 0 && translations.size() != count) || (scale >= 0 && scales.size() != count))
        fail(at, "TRANSLATION and SCALE differ in count");
    const std::vector<glm::dvec4> rotations =
        rotation >= 0 ? read_rotations(model, rotation, count, at) : std::vector<glm::dvec4>();
    std::vector<glm::dmat4> transforms(count);
    for (size_t i = 0; i < count; ++i)
        transforms[i] = trs_matrix(translation >= 0 ? glm::dvec3(translations[i]) : glm::dvec3(0.0),
                                   rotation >= 0 ? rotations[i] : glm::dvec4(0, 0, 0, 1),
                                   scale >= 0 ? glm::dvec3(scales[i]) : glm::dvec3(1.0));
    return transforms;
}

SceneCamera convert_camera(const tinygltf::Camera& camera, const glm::dmat4& world,
                           const std::string& where) {
    const double yfov = camera.perspective.yfov;
    if (!(yfov > 0.0 && yfov < glm::pi<double>())) fail(where, "yfov must lie in (0, pi)");
    const std::optional<glm::dvec3> forward =
        direction_of(glm::dvec3(world * glm::dvec4(0, 0, -1, 0)));
    const glm::dvec3 up_axis(world * glm::dvec4(0, 1, 0, 0));
    const std::optional<glm::dvec3> up =
        forward ? direction_of(up_axis - glm::dot(up_axis, *forward) * *forward) : std::nullopt;
    if (!up) fail(where, "its node's transform collapses the view direction");
    SceneCamera converted;
    converted.position = glm::vec3(world[3]);
    converted.forward = glm::vec3(*forward);
    converted.up = glm::vec3(*up);
    converted.vertical_fov = float(yfov);
    converted.aspect =
        camera.perspective.aspectRatio > 0.0 ? to_float(camera.perspective.aspectRatio, where, "aspectRatio") : 0.0f;
    return converted;
}

} // namespace wf
