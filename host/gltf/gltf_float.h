// gltf_float.h — a number of the file as the float the renderer gets. glTF
// numbers are read as doubles, and a double that passes every check can still
// be Inf as a float (an emissiveStrength of 1e39), or become so once
// multiplied out (an emissive factor times its strength, a node's scale times
// its parent's): such a scene rendered black with exit 0. So the loader checks
// its numbers after the conversion, where the renderer will see them.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace wf {

// `value` as a float; an InputError "where: what is VALUE, not finite as a
// float" (or "what is NaN") where it is not finite.
float to_float(double value, const std::string& where, const std::string& what);

// Every entry of a matrix that will be multiplied out in float; as to_float.
void check_float_range(const glm::dmat4& matrix, const std::string& where, const std::string& what);
// Whether every entry is finite as a float: what check_float_range checks, without a message to build.
bool in_float_range(const glm::dmat4& matrix);

} // namespace wf
