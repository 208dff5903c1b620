// tangents.cpp — see tangents.h.
#include "scene/tangents.h"

#include <cmath>

namespace wf {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

glm::vec3 any_orthogonal(const glm::vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

glm::vec4 orthogonal_tangent(const glm::vec3& n, const glm::vec3& t, float w) {
    const glm::dvec3 nd(n), td(t);
    const glm::dvec3 projected = td - nd * glm::dot(nd, td);
    const double length = glm::length(projected);
    const float handedness = w < 0.0f ? -1.0f : 1.0f;
    // Relative to |t|, so tiny but well-defined tangents survive.
    if (!(length > 1e-6 * glm::length(td)) || !finite(projected) || !(length > 0.0))
        return glm::vec4(any_orthogonal(n), 1.0f);
    return glm::vec4(glm::vec3(projected / length), handedness);
}

std::vector<glm::vec4> generate_tangents(const std::vector<glm::vec3>& positions,
                                         const std::vector<glm::vec3>& normals,
                                         const std::vector<glm::vec2>& uvs,
                                         const std::vector<uint32_t>& corners) {
    const size_t n = positions.size();
    std::vector<glm::dvec3> tangent(n, glm::dvec3(0.0)), bitangent(n, glm::dvec3(0.0)), face(n, glm::dvec3(0.0));
    for (size_t k = 0; k + 2 < corners.size(); k += 3) {
        const uint32_t i0 = corners[k], i1 = corners[k + 1], i2 = corners[k + 2];
        const glm::dvec3 e1 = glm::dvec3(positions[i1]) - glm::dvec3(positions[i0]);
        const glm::dvec3 e2 = glm::dvec3(positions[i2]) - glm::dvec3(positions[i0]);
        const glm::dvec2 d1 = glm::dvec2(uvs[i1]) - glm::dvec2(uvs[i0]);
        const glm::dvec2 d2 = glm::dvec2(uvs[i2]) - glm::dvec2(uvs[i0]);
        const glm::dvec3 area_normal = glm::cross(e1, e2);
        for (uint32_t i : {i0, i1, i2}) face[i] += area_normal;
        const double det = d1.x * d2.y - d2.x * d1.y;
        if (!(std::abs(det) > 0.0) || !std::isfinite(det)) continue;
        // T and B scale with 1/det; times |det| each triangle weighs by its
        // UV area, so slivers with tiny UVs do not dominate a vertex.
        const double weight = std::abs(det) / det;
        const glm::dvec3 t = (e1 * d2.y - e2 * d1.y) * weight;
        const glm::dvec3 b = (e2 * d1.x - e1 * d2.x) * weight;
        if (!finite(t) || !finite(b)) continue;
        for (uint32_t i : {i0, i1, i2}) {
            tangent[i] += t;
            bitangent[i] += b;
        }
    }
    std::vector<glm::vec4> out(n);
    for (size_t i = 0; i < n; ++i) {
        glm::dvec3 normal(normals[i]);
        if (!(glm::length(normal) > 0.0)) normal = face[i];
        const double length = glm::length(normal);
        const glm::vec3 unit = length > 0.0 && std::isfinite(length) ? glm::vec3(normal / length) : glm::vec3(0, 0, 1);
        const double handedness = glm::dot(glm::cross(glm::dvec3(unit), tangent[i]), bitangent[i]);
        out[i] = orthogonal_tangent(unit, glm::vec3(tangent[i]), handedness < 0.0 ? -1.0f : 1.0f);
    }
    return out;
}

} // namespace wf
