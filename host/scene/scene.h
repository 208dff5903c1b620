// scene.h — the scene as loaded, before any device layout: world-space
// triangles with their shading normals and materials, and the camera if the
// file has one. Loaders produce it (gltf_loader.h); device_scene.h turns it
// into the buffers the kernels read.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "wavefront/scene_types.h"
#include "scene/texture_set.h"

namespace wf {

struct EnvironmentMap; // environment_map.h

// glTF 2.0 metallic-roughness with KHR_materials_transmission, _volume
// (its thickness only), _ior, _specular, _clearcoat and _sheen
// (kernels/bsdf/bsdf.h). The defaults here are a plain Lambertian surface (specular 0),
// what scenes built in code mean; the glTF loader sets glTF's own defaults.
struct SceneMaterial {
    std::string name;
    glm::vec3 base_color{0.8f}; // linear, in [0, 1]
    float metallic = 0.0f;
    float roughness = 1.0f;     // perceptual; GGX alpha = roughness^2
    float transmission = 0.0f;
    float ior = 1.5f;
    float specular = 0.0f;      // 0: no specular lobe at all
    glm::vec3 specular_color{1.0f}; // KHR_materials_specular: tints the dielectric layer's F0
    float clearcoat = 0.0f;         // KHR_materials_clearcoat: a coat of ior 1.5 over the rest, this much
    float clearcoat_roughness = 0.0f;
    glm::vec3 sheen_color{0.0f};    // KHR_materials_sheen: fibres' back-scattering over the rest; black: none
    float sheen_roughness = 0.0f;
    glm::vec3 emission{0.0f};   // radiance Le (W sr^-1 m^-2), emitted by the front face
    bool double_sided = false;  // one-sided surfaces emit from the front face only
    // Transmission through a sheet of no thickness, as glTF has it without
    // KHR_materials_volume; scenes built in code are solid.
    bool thin_walled = false;

    // Texture maps, one per WF_TEXTURE_* slot (scene_types.h), indexing
    // Scene::textures; none by default. The factors above multiply them.
    std::array<TextureRef, WF_TEXTURE_SLOTS> textures = no_textures();
    float normal_scale = 1.0f;          // glTF normalTexture.scale
    uint32_t alpha_mode = WF_ALPHA_OPAQUE;
    float alpha_cutoff = 0.5f;          // for WF_ALPHA_MASK
    float base_alpha = 1.0f;            // baseColorFactor's alpha

    bool emits() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
};

// 39.6 degrees, a 50 mm lens on 35 mm film: a camera's field of view when nothing says otherwise.
constexpr float kDefaultVerticalFov = 0.6911f;

struct SceneCamera {
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f}; // unit
    glm::vec3 up{0.0f, 1.0f, 0.0f};       // unit, orthogonal to forward
    float vertical_fov = kDefaultVerticalFov; // radians
    float aspect = 0.0f;                  // width / height; 0 when the file leaves it open
};

struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};
    void grow(const glm::vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    void grow(const Bounds& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
    bool empty() const { return !(lo.x <= hi.x); }
    glm::vec3 center() const { return 0.5f * (lo + hi); }
    glm::vec3 extent() const { return hi - lo; }
};

// A mesh that several nodes place, kept once: Scene's triangles [first,
// first + count), in the mesh's own space, which each MeshInstance maps to
// the world. Such meshes never emit (the loader flattens those: each
// placement of an emitter is a light of its own).
struct SharedMesh {
    uint32_t first = 0;
    uint32_t count = 0;
};

// One placement of a shared mesh: object space to world space, invertible.
struct MeshInstance {
    uint32_t mesh = 0; // index into Scene::shared_meshes
    glm::dmat4 object_to_world{1.0}; // as the loader found it, in double
};

struct Scene {
    // Three entries per triangle, counter-clockwise seen from the front face:
    // in world space, but for the shared meshes' triangles, which come last.
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; // shading normals, per corner; never empty beside positions
    // Per corner like normals when loaded from glTF (zero where the file has
    // none); empty for scenes built in code, which have no texture coordinates.
    std::vector<glm::vec2> uv0, uv1; // TEXCOORD_0 and TEXCOORD_1
    std::vector<glm::vec4> tangents; // xyz unit, orthogonal to the normal; w = ±1: bitangent = cross(n, t) w
    // COLOR_0, linear RGBA per corner, multiplying the base colour and its
    // alpha; white where the file has none, empty for scenes built in code.
    std::vector<glm::vec4> colors;
    std::vector<uint32_t> triangle_material; // one per triangle, index into materials
    std::vector<uint32_t> triangle_mesh;     // one per triangle, index into mesh_names
    std::vector<SceneMaterial> materials;
    std::vector<std::string> mesh_names;
    std::vector<PunctualLight> punctual_lights;           // KHR_lights_punctual, in world space
    std::shared_ptr<const EnvironmentMap> environment; // light from infinitely far; none when null
    TextureSet textures; // what SceneMaterial::textures index
    std::optional<SceneCamera> camera;
    std::vector<std::string> warnings; // each said once, e.g. "mesh 'x': 12 points skipped"
    // Meshes kept once and placed by instances (a two-level BVH,
    // host/bvh/instance_bvh.h); both empty when every triangle is in world space.
    std::vector<SharedMesh> shared_meshes; // in triangle order, after every world-space triangle
    std::vector<MeshInstance> instances;

    size_t triangle_count() const { return triangle_material.size(); }
    // The triangles in world space: all of them, but for the shared meshes'.
    size_t world_triangle_count() const {
        return shared_meshes.empty() ? triangle_count() : size_t{shared_meshes.front().first};
    }
    // The triangles as placed: one per world-space triangle and one per
    // instance of a shared mesh's.
    size_t placed_triangle_count() const {
        size_t placed = world_triangle_count();
        for (const MeshInstance& instance : instances) placed += shared_meshes[instance.mesh].count;
        return placed;
    }
    // The one answer to "is there an emitter": a triangle whose material emits.
    bool has_emissive_triangles() const {
        for (uint32_t material : triangle_material)
            if (materials[material].emits()) return true;
        return false;
    }
    // Whether every triangle that emits takes its emission from a texture:
    // glowing details (DamagedHelmet's, ToyCar's), which light nothing else.
    bool emits_only_through_textures() const {
        bool any = false;
        for (uint32_t material : triangle_material) {
            const SceneMaterial& m = materials[material];
            if (!m.emits()) continue;
            if (m.textures[WF_TEXTURE_EMISSIVE].texture < 0) return false;
            any = true;
        }
        return any;
    }
    bool has_punctual_light() const {
        for (const PunctualLight& light : punctual_lights)
            if (light.intensity[0] > 0.0f || light.intensity[1] > 0.0f || light.intensity[2] > 0.0f) return true;
        return false;
    }
    // Whether any corner's COLOR_0 is not white: only then are colours uploaded.
    bool has_vertex_colors() const {
        for (const glm::vec4& c : colors)
            if (c != glm::vec4(1.0f)) return true;
        return false;
    }
    // Holds every placed triangle: a shared mesh's box mapped by each
    // instance, which for a turned mesh is larger than its triangles' (so the
    // framing of a file without a camera differs a little from that of the
    // scene written out).
    Bounds bounds() const;
};

// The box of the scene's triangles [first, first + count), in their own space.
Bounds triangle_bounds(const Scene& scene, size_t first, size_t count);

// Each shared mesh's box, in its own space.
std::vector<Bounds> shared_mesh_bounds(const Scene& scene);

// `box` mapped by `transform`: the box of its eight corners mapped, in double,
// rounded outward to float.
Bounds transformed_bounds(const Bounds& box, const glm::dmat4& transform);

} // namespace wf
