// gltf_accessors.h — a primitive's attributes and indices read from their
// accessors, checked as tinygltf does not: every element inside its
// bufferView and the view inside its buffer, the formats glTF allows for each
// attribute, sparse substitution applied, finite positions. Each fault is an
// InputError naming `where` (the file and mesh) and the accessor.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace wf {

// The accessor at `index`; `role` names it in messages ("POSITION", "indices").
const tinygltf::Accessor& find_accessor(const tinygltf::Model& model, int index, const std::string& where,
                                        const std::string& role);

// POSITION and NORMAL: VEC3 of FLOAT (other component types would need
// KHR_mesh_quantization, which is not supported).
std::vector<glm::vec3> read_vec3_attribute(const tinygltf::Model& model, int index, const std::string& where,
                                           const std::string& role);

// TEXCOORD_n: VEC2 of FLOAT, or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT
// (glTF 2.0 §3.7.2.1); zeros where the primitive has none (index < 0).
std::vector<glm::vec2> read_texcoords(const tinygltf::Model& model, int index, size_t vertex_count,
                                      const std::string& where, const std::string& role);

// COLOR_0: VEC3 or VEC4 of FLOAT, or of normalized UNSIGNED_BYTE or
// UNSIGNED_SHORT (glTF 2.0 §3.7.2.1), linear RGBA, alpha 1 for VEC3; white
// where the primitive has none (index < 0).
std::vector<glm::vec4> read_colors(const tinygltf::Model& model, int index, size_t vertex_count,
                                   const std::string& where);

// TANGENT: VEC4 of FLOAT, w the handedness.
std::vector<glm::vec4> read_tangents(const tinygltf::Model& model, int index, size_t vertex_count,
                                     const std::string& where);

// EXT_mesh_gpu_instancing's ROTATION: unit quaternions (x, y, z, w), VEC4 of
// FLOAT or of normalized BYTE or SHORT, `count` of them; one of length 0 is an error.
std::vector<glm::dvec4> read_rotations(const tinygltf::Model& model, int index, size_t count,
                                       const std::string& where);

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& where);

void check_finite(const std::vector<glm::vec3>& positions, const std::string& where);

} // namespace wf
