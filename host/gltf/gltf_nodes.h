// gltf_nodes.h — what the scene walk (gltf_loader.cpp) needs of a node: its
// local transform, checked finite, and its camera as a SceneCamera; and a
// node the walk reached, with its world transform, for the lights it holds
// (gltf_lights.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/scene.h"

namespace wf {

// A node the scene walk reached, with its world transform.
struct NodeWorld {
    size_t node;
    glm::dmat4 world;
};

// The node's matrix, or its translation, rotation and scale; an InputError
// naming `where` when an array has the wrong length or the result is not finite.
glm::dmat4 local_transform(const tinygltf::Node& node, const std::string& where);

// EXT_mesh_gpu_instancing: the transforms (TRANSLATION, ROTATION, SCALE) of
// the node's mesh's instances, each applied before the node's own; none where
// the node lacks the extension. An InputError naming `where` for accessors
// that disagree in count or format.
std::vector<glm::dmat4> mesh_instances(const tinygltf::Model& model, const tinygltf::Node& node,
                                       const std::string& where);

// glTF cameras look down their local -Z with +Y up.
SceneCamera convert_camera(const tinygltf::Camera& camera, const glm::dmat4& world, const std::string& where);

} // namespace wf
