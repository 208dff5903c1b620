// gltf_lights.h — glTF's KHR_lights_punctual lights, placed by their nodes'
// world transforms, as the device reads them (PunctualLight in
// include/wavefront/scene_types.h; kernels/lights/punctual.h for the units).
// A light shines from its node's origin along the node's -z axis.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "gltf/gltf_nodes.h"
#include "wavefront/scene_types.h"

namespace wf {

// One light per node in `nodes` that names one. Throws InputError naming
// `path` and the node for a light index out of range, an unknown type, a
// negative or non-finite intensity or colour, or bad cone angles.
std::vector<PunctualLight> punctual_lights(const tinygltf::Model& model, const std::vector<NodeWorld>& nodes,
                                           const std::string& path);

} // namespace wf
