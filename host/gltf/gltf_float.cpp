// gltf_float.cpp — see gltf_float.h.
#include "gltf/gltf_float.h"

#include <cmath>
#include <cstdio>

#include "gltf/gltf_diagnostics.h"

namespace wf {

float to_float(double value, const std::string& where, const std::string& what) {
    const auto converted = static_cast<float>(value);
    if (std::isnan(value)) fail(where, what + " is NaN");
    if (!std::isfinite(converted)) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", value);
        fail(where, what + " is " + text + ", not finite as a float");
    }
    return converted;
}

bool in_float_range(const glm::dmat4& matrix) {
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            if (!std::isfinite(static_cast<float>(matrix[column][row]))) return false;
    return true;
}

void check_float_range(const glm::dmat4& matrix, const std::string& where, const std::string& what) {
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            if (!std::isfinite(static_cast<float>(matrix[column][row]))) // the message only when it fails
                to_float(matrix[column][row], where,
                         what + " entry [" + std::to_string(row) + "][" + std::to_string(column) + "]");
}

} // namespace wf
