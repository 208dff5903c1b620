// gltf_accessors.cpp — see gltf_accessors.h. glTF buffers are little-endian,
// as is every host this runs on.
#include "gltf/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <map>

#include "gltf/gltf_diagnostics.h"

namespace wf {
namespace {

using tinygltf::Accessor;
using tinygltf::Model;

std::string describe_format(const Accessor& accessor) {
    static const std::map<int, const char*> types = {
        {TINYGLTF_TYPE_SCALAR, "SCALAR"}, {TINYGLTF_TYPE_VEC2, "VEC2"},
        {TINYGLTF_TYPE_VEC3, "VEC3"},     {TINYGLTF_TYPE_VEC4, "VEC4"},
        {TINYGLTF_TYPE_MAT2, "MAT2"},     {TINYGLTF_TYPE_MAT3, "MAT3"},
        {TINYGLTF_TYPE_MAT4, "MAT4"}};
    static const std::map<int, const char*> components = {
        {TINYGLTF_COMPONENT_TYPE_BYTE, "BYTE"},
        {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, "UNSIGNED_BYTE"},
        {TINYGLTF_COMPONENT_TYPE_SHORT, "SHORT"},
        {TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, "UNSIGNED_SHORT"},
        {TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, "UNSIGNED_INT"},
        {TINYGLTF_COMPONENT_TYPE_FLOAT, "FLOAT"}};
    const auto name = [](const std::map<int, const char*>& table, int key) {
        const auto it = table.find(key);
        return it == table.end() ? std::to_string(key) : std::string(it->second);
    };
    return name(types, accessor.type) + " of " + name(components, accessor.componentType);
}

// Bytes per component for glTF 2.0's component types; 0 for anything else.
size_t component_size(int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

// glTF buffers are little-endian, as is every host this runs on.
template <typename T>
double load_as_double(const unsigned char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return double(value);
}

// One component of a type component_size() accepts.
double read_component(const unsigned char* bytes, int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return load_as_double<int8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load_as_double<uint8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return load_as_double<int16_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load_as_double<uint16_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load_as_double<uint32_t>(bytes);
    default: return load_as_double<float>(bytes);
    }
}

// Where consecutive elements lie in memory.
struct ElementSpan {
    const unsigned char* first = nullptr;
    size_t stride = 0;
};

// The `count` elements of `element_size` bytes at `offset` in a bufferView,
// checked to lie inside the view, and the view inside its buffer. `what`
// names them in messages ("accessor 2 (POSITION)").
ElementSpan locate_elements(const Model& model, int view_index, size_t offset, size_t count,
                            size_t element_size, const std::string& where,
                            const std::string& what) {
    if (view_index < 0 || size_t(view_index) >= model.bufferViews.size())
        fail(where, what + ": bufferView " + std::to_string(view_index) + " does not exist");
    const tinygltf::BufferView& view = model.bufferViews[size_t(view_index)];
    const std::string view_name = "bufferView " + std::to_string(view_index);
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        fail(where, what + ": " + view_name + " refers to buffer " + std::to_string(view.buffer) +
                        ", which does not exist");
    const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
        fail(where, what + ": " + view_name + " (offset " + std::to_string(view.byteOffset) +
                        ", length " + std::to_string(view.byteLength) +
                        ") runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                        std::to_string(buffer.size()) + " bytes)");
    const size_t stride = view.byteStride != 0 ? view.byteStride : element_size;
    if (stride < element_size)
        fail(where, what + ": " + view_name + " has byteStride " + std::to_string(stride) +
                        ", less than one element (" + std::to_string(element_size) + " bytes)");
    if (count == 0) return {};
    // Written to avoid overflow: the last element must end inside the view.
    const size_t length = view.byteLength;
    if (offset > length || element_size > length - offset ||
        count - 1 > (length - offset - element_size) / stride)
        fail(where, what + " runs past the end of its " + view_name + " (" + std::to_string(count) +
                        " elements of stride " + std::to_string(stride) + " from offset " +
                        std::to_string(offset) + ", view has " + std::to_string(length) +
                        " bytes)");
    return {buffer.data() + view.byteOffset + offset, stride};
}

void decode_elements(const ElementSpan& span, size_t count, size_t components, int component_type,
                     double* out) {
    const size_t component_bytes = component_size(component_type);
    for (size_t i = 0; i < count; ++i)
        for (size_t c = 0; c < components; ++c)
            *out++ =
                read_component(span.first + i * span.stride + c * component_bytes, component_type);
}

// Sparse substitution: the listed elements replace those of the base values.
void apply_sparse(const Model& model, const Accessor& accessor, size_t components,
                  std::vector<double>& values, const std::string& where, const std::string& what) {
    const auto& sparse = accessor.sparse;
    const int index_type = sparse.indices.componentType;
    if (sparse.count < 0 || size_t(sparse.count) > accessor.count)
        fail(where, what + ": sparse count " + std::to_string(sparse.count) + " exceeds its " +
                        std::to_string(accessor.count) + " elements");
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(where,
             what + ": sparse indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        fail(where, what + ": negative sparse byteOffset");

    const size_t count = size_t(sparse.count);
    const ElementSpan index_span =
        locate_elements(model, sparse.indices.bufferView, size_t(sparse.indices.byteOffset), count,
                        component_size(index_type), where, what + " sparse indices");
    const ElementSpan value_span = locate_elements(
        model, sparse.values.bufferView, size_t(sparse.values.byteOffset), count,
        components * component_size(accessor.componentType), where, what + " sparse values");
    std::vector<double> indices(count);
    decode_elements(index_span, count, 1, index_type, indices.data());
    std::vector<double> substitutes(count * components);
    decode_elements(value_span, count, components, accessor.componentType, substitutes.data());
    for (size_t k = 0; k < count; ++k) {
        if (indices[k] >= double(accessor.count))
            fail(where, what + ": sparse index " + std::to_string(uint64_t(indices[k])) +
                            " out of range (" + std::to_string(accessor.count) + " elements)");
        std::copy_n(substitutes.begin() + std::ptrdiff_t(k * components), components,
                    values.begin() + std::ptrdiff_t(size_t(indices[k]) * components));
    }
}

// Every element of a scalar or vector accessor as doubles, `components` per
// element, with sparse substitution applied. Without a bufferView the base
// values are zeros (glTF 2.0 §3.6.2.3). The caller has checked the format.
std::vector<double> read_accessor(const Model& model, const Accessor& accessor,
                                  const std::string& where, const std::string& what) {
    // Indices are at most 32 bits, so no more elements can be addressed.
    if (accessor.count > std::numeric_limits<uint32_t>::max())
        fail(where, what + ": " + std::to_string(accessor.count) + " elements are too many");
    const auto components = size_t(tinygltf::GetNumComponentsInType(uint32_t(accessor.type)));
    std::vector<double> values;
    if (accessor.bufferView >= 0) {
        // Located before allocating, so a count the file cannot back fails cleanly.
        const ElementSpan span =
            locate_elements(model, accessor.bufferView, accessor.byteOffset, accessor.count,
                            components * component_size(accessor.componentType), where, what);
        values.resize(accessor.count * components);
        decode_elements(span, accessor.count, components, accessor.componentType, values.data());
    } else {
        values.assign(accessor.count * components, 0.0);
    }
    if (accessor.sparse.isSparse) apply_sparse(model, accessor, components, values, where, what);
    return values;
}

std::string accessor_name(int index, const std::string& role) {
    return "accessor " + std::to_string(index) + " (" + role + ")";
}

} // namespace

using tinygltf::Accessor;
using tinygltf::Model;

const Accessor& find_accessor(const Model& model, int index, const std::string& where,
                              const std::string& role) {
    if (index < 0 || size_t(index) >= model.accessors.size())
        fail(where, accessor_name(index, role) + " does not exist");
    return model.accessors[size_t(index)];
}

std::vector<glm::vec3> read_vec3_attribute(const Model& model, int index, const std::string& where,
                                           const std::string& role) {
    const Accessor& accessor = find_accessor(model, index, where, role);
    const std::string what = accessor_name(index, role);
    if (accessor.type != TINYGLTF_TYPE_VEC3 ||
        accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        fail(where, what + " must be VEC3 of FLOAT, not " + describe_format(accessor));
    const std::vector<double> values = read_accessor(model, accessor, where, what);
    std::vector<glm::vec3> vectors(accessor.count);
    for (size_t i = 0; i < vectors.size(); ++i)
        vectors[i] = glm::vec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
    return vectors;
}

namespace {

// An attribute of FLOAT or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT
// components, one of `types` (TINYGLTF_TYPE_*), with one element per vertex:
// its values scaled to floats, and its number of components.
std::vector<double> read_normalized(const Model& model, int index, size_t vertex_count, const std::string& where,
                                    const std::string& role, std::initializer_list<int> types, const char* allowed,
                                    int* components) {
    const Accessor& accessor = find_accessor(model, index, where, role);
    const std::string what = accessor_name(index, role);
    const int type = accessor.componentType;
    const double scale = type == TINYGLTF_COMPONENT_TYPE_FLOAT            ? 1.0
                         : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE  ? 1.0 / 255.0
                         : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 1.0 / 65535.0
                                                                          : 0.0;
    if (std::find(types.begin(), types.end(), accessor.type) == types.end() || scale == 0.0 ||
        (type != TINYGLTF_COMPONENT_TYPE_FLOAT && !accessor.normalized))
        fail(where, what + " must be " + allowed + " of FLOAT or normalized UNSIGNED_BYTE or UNSIGNED_SHORT, not " +
                        describe_format(accessor));
    std::vector<double> values = read_accessor(model, accessor, where, what);
    if (accessor.count != vertex_count)
        fail(where, role + " has " + std::to_string(accessor.count) + " elements but POSITION has " +
                        std::to_string(vertex_count));
    for (double& v : values) v *= scale;
    *components = accessor.type == TINYGLTF_TYPE_VEC4 ? 4 : accessor.type == TINYGLTF_TYPE_VEC3 ? 3 : 2;
    return values;
}

} // namespace

std::vector<glm::vec2> read_texcoords(const Model& model, int index, size_t vertex_count,
                                      const std::string& where, const std::string& role) {
    if (index < 0) return std::vector<glm::vec2>(vertex_count, glm::vec2(0.0f));
    int components = 0;
    const std::vector<double> values =
        read_normalized(model, index, vertex_count, where, role, {TINYGLTF_TYPE_VEC2}, "VEC2", &components);
    std::vector<glm::vec2> uv(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i) uv[i] = glm::vec2(values[2 * i], values[2 * i + 1]);
    return uv;
}

std::vector<glm::vec4> read_colors(const Model& model, int index, size_t vertex_count, const std::string& where) {
    if (index < 0) return std::vector<glm::vec4>(vertex_count, glm::vec4(1.0f));
    int n = 0;
    const std::vector<double> values = read_normalized(model, index, vertex_count, where, "COLOR_0",
                                                       {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, "VEC3 or VEC4", &n);
    std::vector<glm::vec4> colors(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i) {
        glm::vec4 c(1.0f);
        for (int k = 0; k < n; ++k) {
            // Floats outside [0, 1] (or NaN) would make the surface emit or absorb nonsense.
            const double v = values[n * i + k];
            if (!(v >= 0.0 && v <= 1.0))
                fail(where, "COLOR_0 element " + std::to_string(i) + " is not in [0, 1]");
            c[k] = float(v);
        }
        colors[i] = c;
    }
    return colors;
}

std::vector<glm::dvec4> read_rotations(const Model& model, int index, size_t count, const std::string& where) {
    const Accessor& accessor = find_accessor(model, index, where, "ROTATION");
    const std::string what = accessor_name(index, "ROTATION");
    const int type = accessor.componentType;
    const double scale = type == TINYGLTF_COMPONENT_TYPE_FLOAT ? 1.0
                         : type == TINYGLTF_COMPONENT_TYPE_BYTE  ? 1.0 / 127.0
                         : type == TINYGLTF_COMPONENT_TYPE_SHORT ? 1.0 / 32767.0
                                                                 : 0.0;
    if (accessor.type != TINYGLTF_TYPE_VEC4 || scale == 0.0 || (type != TINYGLTF_COMPONENT_TYPE_FLOAT && !accessor.normalized))
        fail(where, what + " must be VEC4 of FLOAT or of normalized BYTE or SHORT, not " + describe_format(accessor));
    if (accessor.count != count)
        fail(where, what + " has " + std::to_string(accessor.count) + " elements but the others have " +
                        std::to_string(count));
    const std::vector<double> values = read_accessor(model, accessor, where, what);
    std::vector<glm::dvec4> rotations(count);
    for (size_t i = 0; i < count; ++i) {
        for (int c = 0; c < 4; ++c) // a normalized integer's least value lies below -1 (glTF 2.0 §3.11)
            rotations[i][c] = type == TINYGLTF_COMPONENT_TYPE_FLOAT ? values[4 * i + c] : std::max(values[4 * i + c] * scale, -1.0);
        const double length = glm::length(rotations[i]);
        if (!(length > 0.0) || !std::isfinite(length))
            fail(where, what + ": rotation " + std::to_string(i) + " has no direction");
        rotations[i] /= length;
    }
    return rotations;
}

std::vector<glm::vec4> read_tangents(const Model& model, int index, size_t vertex_count, const std::string& where) {
    const Accessor& accessor = find_accessor(model, index, where, "TANGENT");
    const std::string what = accessor_name(index, "TANGENT");
    if (accessor.type != TINYGLTF_TYPE_VEC4 || accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        fail(where, what + " must be VEC4 of FLOAT, not " + describe_format(accessor));
    if (accessor.count != vertex_count)
        fail(where, "TANGENT has " + std::to_string(accessor.count) + " elements but POSITION has " +
                        std::to_string(vertex_count));
    const std::vector<double> values = read_accessor(model, accessor, where, what);
    std::vector<glm::vec4> tangents(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i)
        tangents[i] = glm::vec4(values[4 * i], values[4 * i + 1], values[4 * i + 2], values[4 * i + 3]);
    return tangents;
}

std::vector<uint32_t> read_indices(const Model& model, int index, const std::string& where) {
    const Accessor& accessor = find_accessor(model, index, where, "indices");
    const std::string what = accessor_name(index, "indices");
    const int type = accessor.componentType;
    if (accessor.type != TINYGLTF_TYPE_SCALAR || (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                                  type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                                  type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail(where, what +
                        " must be SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not " +
                        describe_format(accessor));
    const std::vector<double> values = read_accessor(model, accessor, where, what);
    return std::vector<uint32_t>(values.begin(), values.end());
}

void check_finite(const std::vector<glm::vec3>& positions, const std::string& where) {
    for (size_t i = 0; i < positions.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(positions[i][c]))
                fail(where, "POSITION " + std::to_string(i) + " has " +
                                (std::isnan(positions[i][c]) ? "a NaN " : "an infinite ") +
                                "xyz"[c] + " coordinate");
}

} // namespace wf
