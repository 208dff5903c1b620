// tangents.h — tangent frames for normal mapping where the file has none
// (glTF 2.0 §3.7.2.1 asks for MikkTSpace; this is the classic per-triangle
// UV-derivative construction, which agrees with it on well-behaved meshes:
// Lengyel, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh").
//
// A tangent is a vec4: xyz unit and orthogonal to the shading normal, w = ±1
// the handedness, bitangent = cross(normal, xyz) * w (glTF's convention).
// Never NaN: where the UVs give no direction (degenerate or repeated UVs, zero
// area), any unit vector orthogonal to the normal, with w = 1.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace wf {

// A unit vector orthogonal to unit `n` (Duff et al., "Building an
// Orthonormal Basis, Revisited", 2017).
glm::vec3 any_orthogonal(const glm::vec3& n);

// `t` made orthogonal to unit `n` (Gram–Schmidt) and unit, with handedness
// `w` reduced to ±1; any_orthogonal(n) where nothing of t is left.
glm::vec4 orthogonal_tangent(const glm::vec3& n, const glm::vec3& t, float w);

// Per-vertex tangents of an indexed triangle list (`corners`: three vertex
// indices per triangle): per-triangle tangents and bitangents from the UV
// derivatives, summed per vertex (area-weighted), then orthogonalised against
// the vertex normal. A zero normal (the file has none) is replaced by the sum
// of the adjacent face normals.
std::vector<glm::vec4> generate_tangents(const std::vector<glm::vec3>& positions,
                                         const std::vector<glm::vec3>& normals,
                                         const std::vector<glm::vec2>& uvs,
                                         const std::vector<uint32_t>& corners);

} // namespace wf
