// gltf_loader.cpp — glTF 2.0 into wf::Scene. tinygltf parses the JSON and
// loads the buffers; everything after that is checked here, because tinygltf
// trusts the file: it does not range-check accessors, indices or node
// references, and it parses sparse accessors without applying them.
//
// In load order: read the file, parse it (images kept encoded), check
// extensions, convert materials one to one (decoding the images they use,
// gltf_textures.h), walk the node tree of the default scene instancing each
// mesh's object-space triangles with the node's world matrix, then pick the
// camera among those the walk met.

#include "gltf/gltf_loader.h"

#include <tiny_gltf.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "base/errors.h"
#include "gltf/gltf_lights.h"
#include "gltf/gltf_textures.h"
#include "scene/tangents.h"

namespace wf {
namespace {

using tinygltf::Accessor;
using tinygltf::Model;

// ---------------------------------------------------------------------------
// Messages

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw InputError(where + ": " + what);
}

// "mesh 'floor'", or "mesh 3" where the file leaves it unnamed.
std::string label(const char* kind, size_t index, const std::string& name) {
    return name.empty() ? std::string(kind) + " " + std::to_string(index)
                        : std::string(kind) + " '" + name + "'";
}

// tinygltf's messages span lines and may quote a whole data URI; ours are one
// short line.
std::string one_line(const std::string& text) {
    constexpr size_t kMaxLength = 200;
    std::string line;
    for (char c : text) {
        const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
        if (!space)
            line += c;
        else if (!line.empty() && line.back() != ' ')
            line += ' ';
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (line.size() > kMaxLength) line = line.substr(0, kMaxLength) + "...";
    return line;
}

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

// ---------------------------------------------------------------------------
// Reading and parsing the file

// What tinygltf can take; checked on the file's size before reading it, and
// on bytes handed in directly.
void check_size(const std::string& path, uint64_t size) {
    if (size == 0) fail(path, "empty file");
    // tinygltf takes lengths as unsigned int.
    if (size > std::numeric_limits<unsigned int>::max()) fail(path, "file larger than 4 GiB");
}

std::vector<unsigned char> read_file(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        fail(path, std::filesystem::exists(path, error) ? "not a regular file" : "no such file");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const std::streamoff size = in ? std::streamoff(in.tellg()) : -1;
    if (size < 0) fail(path, "cannot read file");
    check_size(path, uint64_t(size));
    std::vector<unsigned char> bytes(static_cast<size_t>(size));
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), size)) fail(path, "cannot read file");
    return bytes;
}

// External buffers and images must lie in the scene's folder or below it: a
// file from anywhere must not make the renderer read files elsewhere
// ("../../etc/passwd" as a buffer URI).
struct SceneFolder {
    std::filesystem::path root;
    std::string refused; // the first file refused, for the message (tinygltf's own is cut to length)
};

bool read_inside_folder(std::vector<unsigned char>* out, std::string* error, const std::string& file, void* user) {
    SceneFolder& folder = *static_cast<SceneFolder*>(user);
    std::error_code ec;
    const std::filesystem::path relative = std::filesystem::weakly_canonical(file, ec).lexically_relative(folder.root);
    if (ec || relative.empty() || *relative.begin() == "..") {
        if (folder.refused.empty()) folder.refused = file;
        if (error) *error += "outside the scene's folder";
        return false;
    }
    return tinygltf::ReadWholeFile(out, error, file, nullptr);
}

Model parse_model(const std::string& path, const std::vector<unsigned char>& bytes) {
    check_size(path, bytes.size());
    // The magic decides, not the extension: a .gltf may well hold GLB bytes.
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const std::string base_dir = std::filesystem::path(path).parent_path().string();
    const auto length = static_cast<unsigned int>(bytes.size());

    tinygltf::TinyGLTF parser;
    // Images are kept encoded; gltf_textures.cpp decodes those materials use,
    // so a missing or broken image is reported with the material.
    parser.SetImageLoader(keep_image_encoded, nullptr);
    std::error_code ec;
    SceneFolder folder{std::filesystem::weakly_canonical(std::filesystem::absolute(path).parent_path(), ec), {}};
    parser.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &read_inside_folder,
                           &tinygltf::WriteWholeFile, &folder});
    Model model;
    std::string error;
    std::string warning; // only about images, which gltf_textures.cpp reports itself
    bool parsed = false;
    try {
        parsed = binary ? parser.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(),
                                                      length, base_dir)
                        : parser.LoadASCIIFromString(&model, &error, &warning,
                                                     reinterpret_cast<const char*>(bytes.data()),
                                                     length, base_dir);
    } catch (const std::exception& e) { // tinygltf's own checks can throw (std::vector::at)
        error = e.what();
    }
    if (!parsed && !folder.refused.empty())
        fail(path, "refers to " + folder.refused + ", which lies outside the scene's folder");
    if (!parsed) {
        const std::string detail = one_line(error);
        fail(path, std::string(binary ? "cannot load GLB" : "cannot load glTF") +
                       (detail.empty() ? "" : ": " + detail));
    }
    return model;
}

// ---------------------------------------------------------------------------
// Extensions and materials

const std::set<std::string>& supported_extensions() {
    static const std::set<std::string> names = {"KHR_materials_emissive_strength", "KHR_materials_ior",
                                                "KHR_materials_specular", "KHR_materials_transmission",
                                                "KHR_texture_transform"};
    return names;
}

void check_extensions(const Model& model, const std::string& path,
                      std::vector<std::string>& warnings) {
    for (const std::string& name : model.extensionsRequired)
        if (!supported_extensions().count(name))
            fail(path, "required extension " + name + " is not supported");
    std::string ignored;
    for (const std::string& name : model.extensionsUsed)
        if (!supported_extensions().count(name)) ignored += (ignored.empty() ? "" : ", ") + name;
    if (!ignored.empty()) warnings.push_back("extensions not supported, ignored: " + ignored);
}

// Core glTF features that are read past, each said once: the scene renders
// in its bind pose with no morph weights applied.
void check_core_features(const Model& model, std::vector<std::string>& warnings) {
    if (!model.skins.empty())
        warnings.push_back(std::to_string(model.skins.size()) + " skin(s) not supported, rendered in the bind pose");
    size_t morphed = 0;
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& primitive : mesh.primitives) morphed += !primitive.targets.empty();
    if (morphed)
        warnings.push_back("morph targets not supported on " + std::to_string(morphed) +
                           " primitive(s), rendered without them");
    if (!model.animations.empty())
        warnings.push_back(std::to_string(model.animations.size()) +
                           " animation(s) not supported, rendered at rest");
}

// tinygltf fills defaults but does not check every array's length.
double element_or(const std::vector<double>& values, size_t i, double fallback) {
    return i < values.size() ? values[i] : fallback;
}

// A number from a material extension's object, or `fallback` where the
// extension or the property is absent.
double extension_number(const tinygltf::Material& material, const char* extension_name,
                        const char* property, double fallback) {
    const auto extension = material.extensions.find(extension_name);
    if (extension == material.extensions.end() || !extension->second.Has(property)) return fallback;
    const tinygltf::Value& value = extension->second.Get(property);
    return value.IsNumber() ? value.GetNumberAsDouble() : fallback;
}

// A factor that glTF defines on [0, 1]: NaN is an error, the rest is clamped.
float unit_factor(double value, const std::string& where, const char* what) {
    if (std::isnan(value)) fail(where, std::string(what) + " is NaN");
    return float(std::clamp(value, 0.0, 1.0));
}

SceneMaterial convert_material(const tinygltf::Material& material, size_t index,
                               const std::string& path) {
    const std::string where = path + ": " + label("material", index, material.name);
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    SceneMaterial converted;
    converted.name = material.name;
    converted.double_sided = material.doubleSided;
    converted.metallic = unit_factor(pbr.metallicFactor, where, "metallicFactor");
    converted.roughness = unit_factor(pbr.roughnessFactor, where, "roughnessFactor");
    converted.transmission = unit_factor(
        extension_number(material, "KHR_materials_transmission", "transmissionFactor", 0.0), where,
        "transmissionFactor");
    converted.specular = unit_factor(
        extension_number(material, "KHR_materials_specular", "specularFactor", 1.0), where, "specularFactor");
    // KHR_materials_ior allows 0 as "a perfect absorber"; that, and anything below 1, is not supported.
    const double ior = extension_number(material, "KHR_materials_ior", "ior", 1.5);
    if (!(ior >= 1.0 && ior < 1e3)) fail(where, "ior " + std::to_string(ior) + " is not in [1, 1000)");
    converted.ior = float(ior);
    const double strength = extension_number(material, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
    for (int c = 0; c < 3; ++c) {
        converted.base_color[c] = unit_factor(element_or(pbr.baseColorFactor, size_t(c), 1.0), where,
                                              "baseColorFactor");
        const double emission = element_or(material.emissiveFactor, size_t(c), 0.0) * strength;
        if (!std::isfinite(emission) || emission < 0.0)
            fail(where, "emission must be finite and non-negative");
        converted.emission[c] = float(emission);
    }
    return converted;
}

// glTF's defaults for a primitive without a material: white, metallic 1,
// roughness 1 (glTF 2.0, section 3.9.6), not emissive.
SceneMaterial default_material() {
    SceneMaterial material;
    material.name = "default";
    material.base_color = glm::vec3(1.0f);
    material.metallic = 1.0f;
    material.roughness = 1.0f;
    material.specular = 1.0f;
    return material;
}

// ---------------------------------------------------------------------------
// Accessors

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

const Accessor& find_accessor(const Model& model, int index, const std::string& where,
                              const std::string& role) {
    if (index < 0 || size_t(index) >= model.accessors.size())
        fail(where, accessor_name(index, role) + " does not exist");
    return model.accessors[size_t(index)];
}

// POSITION and NORMAL: VEC3 of FLOAT (other component types would need
// KHR_mesh_quantization, which is not supported).
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

// TEXCOORD_n: VEC2 of FLOAT, or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT
// (glTF 2.0 §3.7.2.1); zeros where the primitive has none.
std::vector<glm::vec2> read_texcoords(const Model& model, int index, size_t vertex_count,
                                      const std::string& where, const std::string& role) {
    if (index < 0) return std::vector<glm::vec2>(vertex_count, glm::vec2(0.0f));
    const Accessor& accessor = find_accessor(model, index, where, role);
    const std::string what = accessor_name(index, role);
    const int type = accessor.componentType;
    const double scale = type == TINYGLTF_COMPONENT_TYPE_FLOAT            ? 1.0
                         : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE  ? 1.0 / 255.0
                         : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 1.0 / 65535.0
                                                                          : 0.0;
    if (accessor.type != TINYGLTF_TYPE_VEC2 || scale == 0.0 ||
        (type != TINYGLTF_COMPONENT_TYPE_FLOAT && !accessor.normalized))
        fail(where, what + " must be VEC2 of FLOAT or normalized UNSIGNED_BYTE or UNSIGNED_SHORT, not " +
                        describe_format(accessor));
    const std::vector<double> values = read_accessor(model, accessor, where, what);
    if (accessor.count != vertex_count)
        fail(where, role + " has " + std::to_string(accessor.count) + " elements but POSITION has " +
                        std::to_string(vertex_count));
    std::vector<glm::vec2> uv(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i) uv[i] = glm::vec2(values[2 * i] * scale, values[2 * i + 1] * scale);
    return uv;
}

// TANGENT: VEC4 of FLOAT, w the handedness.
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

// ---------------------------------------------------------------------------
// Primitives

bool is_triangle_mode(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// Three vertex indices per triangle, strips and fans unrolled with the
// winding glTF 2.0 §3.7.2.1 gives them, so the front face stays the same.
std::vector<uint32_t> triangle_corners(int mode, const std::vector<uint32_t>& v) {
    std::vector<uint32_t> corners;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        corners.assign(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 3 * 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 0; i + 2 < v.size(); ++i) {
            const size_t odd = i % 2;
            corners.insert(corners.end(), {v[i], v[i + 1 + odd], v[i + 2 - odd]});
        }
    } else { // TINYGLTF_MODE_TRIANGLE_FAN
        for (size_t i = 0; i + 2 < v.size(); ++i)
            corners.insert(corners.end(), {v[i + 1], v[i + 2], v[0]});
    }
    return corners;
}

// What a mesh holds that cannot be rendered, reported in one warning per mesh.
struct SkippedElements {
    size_t points = 0;
    size_t lines = 0;
    size_t primitives_without_position = 0;

    // `vertices`: the length of the primitive's vertex stream.
    void add(int mode, size_t vertices) {
        switch (mode) {
        case TINYGLTF_MODE_POINTS: points += vertices; break;
        case TINYGLTF_MODE_LINE: lines += vertices / 2; break;
        case TINYGLTF_MODE_LINE_LOOP: lines += vertices >= 2 ? vertices : 0; break;
        default: lines += vertices >= 2 ? vertices - 1 : 0; break; // TINYGLTF_MODE_LINE_STRIP
        }
    }

    std::string describe() const {
        std::string parts;
        const auto add_part = [&parts](size_t n, const char* noun) {
            if (n > 0) parts += (parts.empty() ? "" : ", ") + std::to_string(n) + " " + noun;
        };
        add_part(points, "points");
        add_part(lines, "lines");
        add_part(primitives_without_position, "primitives without POSITION");
        return parts.empty() ? parts : parts + " skipped";
    }
};

// One glTF mesh's triangles in the mesh's own space, built once however many
// nodes instance it.
struct MeshTriangles {
    std::vector<glm::vec3> positions; // three per triangle
    std::vector<glm::vec3> normals;   // three per triangle; zero where the file has none
    std::vector<glm::vec2> uv0, uv1;  // three per triangle; zero where the file has none
    std::vector<glm::vec4> tangents;  // three per triangle; the file's, or generated (tangents.h)
    std::vector<uint32_t> materials;  // one per triangle, index into Scene::materials
    uint32_t name_index = 0;          // into Scene::mesh_names
};

// `v` scaled to unit length, or nothing where it has no direction (zero or not
// finite).
std::optional<glm::dvec3> direction_of(const glm::dvec3& v) {
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    return v / length;
}

// ---------------------------------------------------------------------------
// Nodes and cameras

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
        if (!node.translation.empty())
            transform = glm::translate(transform, glm::make_vec3(node.translation.data()));
        if (!node.rotation.empty()) { // glTF stores x, y, z, w; glm's constructor takes w first
            const std::vector<double>& q = node.rotation;
            transform *= glm::mat4_cast(glm::normalize(glm::dquat(q[3], q[0], q[1], q[2])));
        }
        if (!node.scale.empty())
            transform = glm::scale(transform, glm::make_vec3(node.scale.data()));
    }
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            if (!std::isfinite(transform[column][row])) fail(where, "transform is not finite");
    return transform;
}

// glTF cameras look down their local -Z with +Y up.
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
        camera.perspective.aspectRatio > 0.0 ? float(camera.perspective.aspectRatio) : 0.0f;
    return converted;
}

// ---------------------------------------------------------------------------
// The scene

class SceneBuilder {
public:
    SceneBuilder(const Model& model, const std::string& path)
        : model_(model), path_(path), meshes_(model.meshes.size()) {}

    Scene build(const LoadOptions& options) {
        check_extensions(model_, path_, scene_.warnings);
        check_core_features(model_, scene_.warnings);
        convert_materials();
        std::vector<bool> on_path(model_.nodes.size(), false);
        for (int root : root_nodes()) visit(root, glm::dmat4(1.0), on_path);
        if (scene_.triangle_count() == 0) fail(path_, "the scene has no triangles");
        scene_.punctual_lights = punctual_lights(model_, visited_, path_);
        scene_.camera = choose_camera(options);
        return std::move(scene_);
    }

private:
    // A camera the node walk met, with its node's world matrix.
    struct PlacedCamera {
        size_t camera;
        glm::dmat4 world;
    };

    // Scene::materials mirrors the file's materials index for index; the
    // default material, if needed, comes after them.
    void convert_materials() {
        GltfTextures textures(model_, path_, scene_.textures);
        for (size_t i = 0; i < model_.materials.size(); ++i) {
            scene_.materials.push_back(convert_material(model_.materials[i], i, path_));
            textures.convert(model_.materials[i], i, scene_.materials.back()); // gltf_textures.h
        }
        for (std::string& warning : textures.warnings()) scene_.warnings.push_back(std::move(warning));
    }

    uint32_t material_index(int gltf_material, const std::string& where) {
        if (gltf_material >= 0) {
            if (size_t(gltf_material) >= model_.materials.size())
                fail(where, "material " + std::to_string(gltf_material) + " does not exist");
            return uint32_t(gltf_material);
        }
        if (!default_material_) {
            default_material_ = uint32_t(scene_.materials.size());
            scene_.materials.push_back(default_material());
        }
        return *default_material_;
    }

    // The default scene's roots; without scenes, every node no other node
    // lists as a child.
    std::vector<int> root_nodes() const {
        if (!model_.scenes.empty()) {
            const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (size_t(scene) >= model_.scenes.size())
                fail(path_, "default scene " + std::to_string(scene) + " does not exist");
            return model_.scenes[size_t(scene)].nodes;
        }
        std::vector<bool> is_child(model_.nodes.size(), false);
        for (const tinygltf::Node& node : model_.nodes)
            for (int child : node.children)
                if (child >= 0 && size_t(child) < is_child.size()) is_child[size_t(child)] = true;
        std::vector<int> roots;
        for (size_t i = 0; i < is_child.size(); ++i)
            if (!is_child[i]) roots.push_back(int(i));
        return roots;
    }

    void visit(int node_index, const glm::dmat4& parent_world, std::vector<bool>& on_path) {
        if (node_index < 0 || size_t(node_index) >= model_.nodes.size())
            fail(path_, "node " + std::to_string(node_index) + " does not exist");
        const auto index = size_t(node_index);
        const tinygltf::Node& node = model_.nodes[index];
        const std::string where = path_ + ": " + label("node", index, node.name);
        if (on_path[index]) fail(where, "the node is its own ancestor");

        const glm::dmat4 world = parent_world * local_transform(node, where);
        visited_.push_back({index, world});
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= model_.meshes.size())
                fail(where, "mesh " + std::to_string(node.mesh) + " does not exist");
            instance(size_t(node.mesh), world, where);
        }
        if (node.camera >= 0) {
            if (size_t(node.camera) >= model_.cameras.size())
                fail(where, "camera " + std::to_string(node.camera) + " does not exist");
            cameras_.push_back({size_t(node.camera), world});
        }
        on_path[index] = true;
        for (int child : node.children) visit(child, world, on_path);
        on_path[index] = false;
    }

    // Appends one instance of a mesh in world space. A mirroring transform
    // swaps two corners so counter-clockwise stays the front face; normals go
    // through the inverse transpose, and fall back to the geometric normal
    // where the file has none or they do not survive the transform. A
    // transform that carries a finite vertex past float range is an error.
    void instance(size_t mesh_index, const glm::dmat4& world, const std::string& node_where) {
        const MeshTriangles& mesh = mesh_triangles(mesh_index);
        const glm::dmat3 linear(world);
        const glm::dmat3 normal_matrix = glm::inverseTranspose(linear);
        const bool mirrored = glm::determinant(linear) < 0.0;
        const std::array<size_t, 3> order = mirrored
                                                ? std::array<size_t, 3>{0, 2, 1}
                                                : std::array<size_t, 3>{0, 1, 2};
        for (size_t triangle = 0; triangle < mesh.materials.size(); ++triangle) {
            std::array<glm::dvec3, 3> p;
            for (size_t k = 0; k < 3; ++k)
                p[k] = glm::dvec3(world * glm::dvec4(mesh.positions[3 * triangle + order[k]], 1.0));
            // A quarter of float range, so that the BVH's centroids (a sum of
            // three corners) and bounds extents (a difference of two) stay
            // finite: past it the builder computed inf * 0 (found by fuzzing).
            constexpr double kMaxCoordinate = double(std::numeric_limits<float>::max()) / 4.0;
            for (size_t k = 0; k < 3; ++k)
                if (!glm::all(glm::lessThanEqual(glm::abs(p[k]), glm::dvec3(kMaxCoordinate))))
                    fail(node_where + ": " + label("mesh", mesh_index, model_.meshes[mesh_index].name),
                         "vertex " + std::to_string(3 * triangle + order[k]) +
                             " leaves float range (a quarter of FLT_MAX) after the node transform");
            // Degenerate triangles stay (later stages handle them) with any unit normal.
            const glm::dvec3 geometric =
                direction_of(glm::cross(p[1] - p[0], p[2] - p[0])).value_or(glm::dvec3(0, 0, 1));
            for (size_t k = 0; k < 3; ++k) {
                const size_t corner = 3 * triangle + order[k];
                const glm::dvec3 normal = normal_matrix * glm::dvec3(mesh.normals[corner]);
                const glm::vec3 unit_normal(direction_of(normal).value_or(geometric));
                scene_.positions.push_back(glm::vec3(p[k]));
                scene_.normals.push_back(unit_normal);
                scene_.uv0.push_back(mesh.uv0[corner]);
                scene_.uv1.push_back(mesh.uv1[corner]);
                // Tangents move with the surface (not the inverse transpose);
                // a mirroring transform flips the handedness.
                const glm::vec4 t = mesh.tangents[corner];
                scene_.tangents.push_back(orthogonal_tangent(unit_normal, glm::vec3(linear * glm::dvec3(t)),
                                                             mirrored ? -t.w : t.w));
            }
            scene_.triangle_material.push_back(mesh.materials[triangle]);
            scene_.triangle_mesh.push_back(mesh.name_index);
        }
    }

    const MeshTriangles& mesh_triangles(size_t mesh_index) {
        std::optional<MeshTriangles>& cached = meshes_[mesh_index];
        if (!cached) cached = build_mesh(mesh_index);
        return *cached;
    }

    MeshTriangles build_mesh(size_t mesh_index) {
        const tinygltf::Mesh& mesh = model_.meshes[mesh_index];
        const std::string mesh_label = label("mesh", mesh_index, mesh.name);
        const std::string where = path_ + ": " + mesh_label;
        MeshTriangles triangles;
        SkippedElements skipped;
        for (const tinygltf::Primitive& primitive : mesh.primitives)
            append_primitive(primitive, where, triangles, skipped);
        if (!skipped.describe().empty())
            scene_.warnings.push_back(mesh_label + ": " + skipped.describe());
        if (!triangles.materials.empty()) {
            triangles.name_index = uint32_t(scene_.mesh_names.size());
            scene_.mesh_names.push_back(mesh.name.empty() ? mesh_label : mesh.name);
        }
        return triangles;
    }

    void append_primitive(const tinygltf::Primitive& primitive, const std::string& where,
                          MeshTriangles& out, SkippedElements& skipped) {
        const auto attribute = [&primitive](const char* name) {
            const auto it = primitive.attributes.find(name);
            return it == primitive.attributes.end() ? -1 : it->second;
        };
        const int position_accessor = attribute("POSITION");
        if (primitive.mode < TINYGLTF_MODE_POINTS || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
            fail(where, "unknown primitive mode " + std::to_string(primitive.mode));
        // glTF 2.0 §3.7.2.1: a primitive without positions is not rendered.
        if (position_accessor < 0) {
            ++skipped.primitives_without_position;
            return;
        }
        if (!is_triangle_mode(primitive.mode)) {
            const bool indexed = primitive.indices >= 0;
            skipped.add(primitive.mode,
                        find_accessor(model_, indexed ? primitive.indices : position_accessor,
                                      where, indexed ? "indices" : "POSITION")
                            .count);
            return;
        }

        const std::vector<glm::vec3> positions =
            read_vec3_attribute(model_, position_accessor, where, "POSITION");
        check_finite(positions, where);
        std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
        if (const int normal_accessor = attribute("NORMAL"); normal_accessor >= 0) {
            normals = read_vec3_attribute(model_, normal_accessor, where, "NORMAL");
            if (normals.size() != positions.size())
                fail(where, "NORMAL has " + std::to_string(normals.size()) +
                                " elements but POSITION has " + std::to_string(positions.size()));
        }
        std::vector<uint32_t> vertices(positions.size());
        if (primitive.indices >= 0)
            vertices = read_indices(model_, primitive.indices, where);
        else
            std::iota(vertices.begin(), vertices.end(), 0u);
        for (uint32_t vertex : vertices)
            if (vertex >= positions.size())
                fail(where, "index " + std::to_string(vertex) + " out of range (" +
                                std::to_string(positions.size()) + " vertices)");

        const uint32_t material = material_index(primitive.material, where);
        const std::vector<glm::vec2> uv0 = read_texcoords(model_, attribute("TEXCOORD_0"), positions.size(), where, "TEXCOORD_0");
        const std::vector<glm::vec2> uv1 = read_texcoords(model_, attribute("TEXCOORD_1"), positions.size(), where, "TEXCOORD_1");
        const std::vector<uint32_t> corners = triangle_corners(primitive.mode, vertices);
        // Generated from the UV set the material's normal map reads.
        const int tangent_accessor = attribute("TANGENT");
        const bool normal_map_uv1 = scene_.materials[material].textures[WF_TEXTURE_NORMAL].texcoord == 1u;
        const std::vector<glm::vec4> tangents =
            tangent_accessor >= 0 ? read_tangents(model_, tangent_accessor, positions.size(), where)
                                  : generate_tangents(positions, normals, normal_map_uv1 ? uv1 : uv0, corners);
        for (uint32_t corner : corners) {
            out.positions.push_back(positions[corner]);
            out.normals.push_back(normals[corner]);
            out.uv0.push_back(uv0[corner]);
            out.uv1.push_back(uv1[corner]);
            out.tangents.push_back(tangents[corner]);
        }
        out.materials.resize(out.positions.size() / 3, material);
    }

    std::optional<SceneCamera> choose_camera(const LoadOptions& options) const {
        const auto is_perspective = [this](size_t camera) {
            return model_.cameras[camera].type == "perspective";
        };
        if (options.camera_index < 0) {
            for (const PlacedCamera& placed : cameras_)
                if (is_perspective(placed.camera)) return convert_placed(placed);
            return std::nullopt;
        }
        const auto wanted = size_t(options.camera_index);
        if (wanted >= model_.cameras.size())
            fail(path_, "camera " + std::to_string(wanted) + " does not exist (the file has " +
                            std::to_string(model_.cameras.size()) + ")");
        const tinygltf::Camera& camera = model_.cameras[wanted];
        if (!is_perspective(wanted))
            fail(path_, label("camera", wanted, camera.name) + " is not perspective (type '" +
                            camera.type + "')");
        for (const PlacedCamera& placed : cameras_)
            if (placed.camera == wanted) return convert_placed(placed);
        fail(path_, label("camera", wanted, camera.name) + " is not placed in the scene");
    }

    SceneCamera convert_placed(const PlacedCamera& placed) const {
        const tinygltf::Camera& camera = model_.cameras[placed.camera];
        return convert_camera(camera, placed.world,
                              path_ + ": " + label("camera", placed.camera, camera.name));
    }

    const Model& model_;
    const std::string& path_;
    Scene scene_;
    std::vector<std::optional<MeshTriangles>> meshes_; // by glTF mesh index, built on first use
    std::optional<uint32_t> default_material_;
    std::vector<PlacedCamera> cameras_; // in the order the node walk met them
    std::vector<NodeWorld> visited_;    // every node the walk reached, for its lights
};

// Both entry points; the file is read from `path` when `given` is null.
Scene load(const std::string& path, const std::vector<unsigned char>* given, const LoadOptions& options) {
    try {
        const std::vector<unsigned char> read = given ? std::vector<unsigned char>() : read_file(path);
        const Model model = parse_model(path, given ? *given : read);
        return SceneBuilder(model, path).build(options);
    } catch (const std::bad_alloc&) { // an accessor without a bufferView may claim any count
        throw InputError(path + ": not enough memory to load the file");
    }
}

} // namespace

Scene load_gltf(const std::string& path, const LoadOptions& options) {
    return load(path, nullptr, options);
}

Scene load_gltf_bytes(const std::string& path, const std::vector<unsigned char>& bytes, const LoadOptions& options) {
    return load(path, &bytes, options);
}

} // namespace wf
