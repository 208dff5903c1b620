// device_scene.cpp — reorders the loaded triangles into BVH order and builds
// the light table: each emissive triangle is weighted by its power,
// π · area · mean(Le), doubled when it emits from both faces, less what a
// clear coat over it reflects back (bsdf/coat_fresnel.h); Le under an
// emissive texture is the texture's mean over the triangle
// (textured_emission.h), and a triangle whose texels are all black is no light.
#include "device/device_scene.h"

#include <algorithm>

#include "base/alias_table.h"
#include "bsdf/albedo_tables.h"
#include "bsdf/coat_fresnel.h"
#include "device/device_buffer.h"
#include "device/textured_emission.h"
#include "scene/environment_map.h"

namespace wf {
namespace {

void store3(float* out, const glm::vec3& v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

double triangle_power(const Scene& scene, const TexturedEmission& textured, uint32_t t) {
    const SceneMaterial& m = scene.materials[scene.triangle_material[t]];
    if (!m.emits()) return 0.0;
    const glm::dvec3 a(scene.positions[3 * t]), b(scene.positions[3 * t + 1]), c(scene.positions[3 * t + 2]);
    const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    const glm::dvec3 texture = textured.mean(t);
    const double radiance = (m.emission.x * texture.x + m.emission.y * texture.y + m.emission.z * texture.z) / 3.0;
    return 3.14159265358979323846 * area * radiance * (m.double_sided ? 2.0 : 1.0) *
           wf_device::coat_emission_mean(m.clearcoat);
}

double mean3(const float* v) { return (double(v[0]) + v[1] + v[2]) / 3.0; }

// The power that light choice is proportional to (pbrt-v4's PowerLightSampler):
// lights far away or at infinity deliver theirs through a disk of the scene's
// radius.
double punctual_power(const PunctualLight& light, double scene_radius) {
    constexpr double pi = 3.14159265358979323846;
    const double intensity = mean3(light.intensity);
    if (light.type == WF_PUNCTUAL_DIRECTIONAL) return pi * scene_radius * scene_radius * intensity;
    if (light.type == WF_PUNCTUAL_SPOT)
        return 2.0 * pi * (1.0 - 0.5 * (double(light.cos_inner) + light.cos_outer)) * intensity;
    return 4.0 * pi * intensity;
}

double environment_power(const EnvironmentMap& map, double scene_radius) {
    constexpr double pi = 3.14159265358979323846;
    const Environment& e = map.header;
    double radiance_integral = 0.0; // of mean radiance over the sphere, W m^-2
    if (e.flags & WF_ENVIRONMENT_CONSTANT) {
        radiance_integral = 4.0 * pi * mean3(e.scale);
    } else {
        for (uint32_t row = 0; row < e.height; ++row) {
            const double solid_angle = (2.0 * pi / e.width) * (std::cos(pi * row / e.height) -
                                                               std::cos(pi * (row + 1) / e.height));
            for (uint32_t col = 0; col < e.width; ++col) {
                const float* t = &map.texels[4 * (size_t{row} * e.width + col)];
                radiance_integral += solid_angle * (double(t[0]) * e.scale[0] + double(t[1]) * e.scale[1] +
                                                    double(t[2]) * e.scale[2]) / 3.0;
            }
        }
    }
    return pi * scene_radius * scene_radius * radiance_integral;
}

} // namespace

DeviceSceneData make_device_scene_data(const Scene& scene, const Bvh& bvh) {
    DeviceSceneData d;
    d.nodes = bvh.nodes;
    d.instances = bvh.instances;
    const size_t n = bvh.order.size(); // a multiple of WF_BLOCK_LANES
    d.triangles.resize(n / WF_BLOCK_LANES);
    d.normals.resize(n);
    std::vector<double> light_weights;
    const TexturedEmission textured(scene);
    const auto add_light = [&](uint32_t kind, uint32_t index, double power) {
        d.lights.push_back(LightEntry{0.0f, 0u, index, 0.0f, kind, {0u, 0u, 0u}});
        light_weights.push_back(power);
    };
    // Emissive triangles join the light list in the scene's order, not the
    // tree's, so that which one a sample picks does not hang on how the BVH
    // was built (a scene and its instanced twin, or two builders, draw alike).
    struct Emitter {
        uint32_t triangle, position;
        double power;
    };
    std::vector<Emitter> emitters;
    for (size_t i = 0; i < n; ++i) {
        TriangleBlock& block = d.triangles[i / WF_BLOCK_LANES];
        const size_t lane = i % WF_BLOCK_LANES;
        // A lane no leaf uses repeats lane 0, always a triangle, so that its
        // arithmetic in the leaf test stays that of a real triangle.
        const uint32_t t = bvh.order[i] != kNoTriangle ? bvh.order[i] : bvh.order[i - lane];
        for (size_t c = 0; c < 3; ++c)
            for (int axis = 0; axis < 3; ++axis) block.corners[3 * c + axis][lane] = scene.positions[3 * t + c][axis];
        block.light[lane] = -1;
        block.material[lane] = scene.triangle_material[t];
        if (bvh.order[i] == kNoTriangle) continue; // its normals stay zero, as resize made them
        TriangleNormals& nrm = d.normals[i];
        store3(nrm.n0, scene.normals[3 * t]);
        store3(nrm.n1, scene.normals[3 * t + 1]);
        store3(nrm.n2, scene.normals[3 * t + 2]);
        if (const double power = triangle_power(scene, textured, t); power > 0.0)
            emitters.push_back({t, static_cast<uint32_t>(i), power});
    }
    std::sort(emitters.begin(), emitters.end(),
              [](const Emitter& a, const Emitter& b) { return a.triangle < b.triangle; });
    for (const Emitter& e : emitters) {
        d.triangles[e.position / WF_BLOCK_LANES].light[e.position % WF_BLOCK_LANES] =
            static_cast<int32_t>(d.lights.size());
        add_light(WF_LIGHT_TRIANGLE, e.position, e.power);
    }
    d.emissive_triangles = static_cast<uint32_t>(d.lights.size());
    add_texture_data(scene, bvh.order, d);
    const Bounds bounds = scene.bounds();
    d.scene_diameter = bounds.empty() ? 0.0f : glm::length(bounds.extent());
    const double radius = 0.5 * d.scene_diameter;
    d.punctual = scene.punctual_lights;
    for (size_t i = 0; i < d.punctual.size(); ++i)
        if (const double power = punctual_power(d.punctual[i], radius); power > 0.0)
            add_light(WF_LIGHT_PUNCTUAL, static_cast<uint32_t>(i), power);
    if (scene.environment) {
        d.environment = scene.environment->header;
        d.environment_texels = scene.environment->texels;
        d.environment_distribution = scene.environment->distribution;
        if (const double power = environment_power(*scene.environment, radius); power > 0.0) {
            d.environment_light = static_cast<uint32_t>(d.lights.size());
            add_light(WF_LIGHT_ENVIRONMENT, 0u, power);
        }
    }
    if (!light_weights.empty()) {
        const std::vector<AliasEntry> table = build_alias_table(light_weights);
        for (size_t i = 0; i < table.size(); ++i) {
            d.lights[i].probability = table[i].probability;
            d.lights[i].alias = table[i].alias;
            d.lights[i].pmf = table[i].pmf;
        }
    }
    for (const SceneMaterial& m : scene.materials) {
        Material dm{};
        store3(dm.base_color, glm::clamp(m.base_color, 0.0f, 1.0f));
        dm.metallic = m.metallic;
        dm.roughness = m.roughness;
        dm.transmission = m.transmission;
        dm.ior = m.ior;
        dm.specular = m.specular;
        store3(dm.specular_color, m.specular_color);
        dm.clearcoat = m.clearcoat;
        dm.clearcoat_roughness = m.clearcoat_roughness;
        store3(dm.sheen_color, m.sheen_color);
        dm.sheen_roughness = m.sheen_roughness;
        store3(dm.emission, m.emission);
        dm.thin_walled = m.thin_walled ? 1.0f : 0.0f;
        dm.flags = m.double_sided ? WF_MATERIAL_DOUBLE_SIDED : 0u;
        d.materials.push_back(dm);
    }
    // A GPU's program reads the glass table from here (bsdf/albedo.h); only glass reads it at all.
    const bool glass = std::any_of(scene.materials.begin(), scene.materials.end(),
                                   [](const SceneMaterial& m) { return m.transmission > 0.0f; });
    if (glass) {
        const float* table = &wf_device::glass_albedo_table[0][0][0][0];
        d.glass_albedo.assign(table, table + sizeof(wf_device::glass_albedo_table) / sizeof(float));
    }
    // A material reads COLOR_0 where any of its corners is not white (add_texture_data uploads them all).
    if (!d.colors.empty())
        for (size_t t = 0; t < scene.triangle_count(); ++t)
            for (size_t k = 0; k < 3; ++k)
                if (scene.colors[3 * t + k] != glm::vec4(1.0f))
                    d.materials[scene.triangle_material[t]].flags |= WF_MATERIAL_VERTEX_COLORS;
    return d;
}

size_t DeviceSceneData::bytes() const {
    size_t bytes = 0;
#define WF_ADD_BYTES(type, name, what) bytes += name.size() * sizeof(type);
    WF_SCENE_BUFFERS(WF_ADD_BYTES)
#undef WF_ADD_BYTES
    return bytes;
}

size_t DeviceSceneData::traversal_bytes() const {
    return nodes.size() * sizeof(BvhNode) + triangles.size() * sizeof(TriangleBlock);
}

size_t DeviceSceneData::largest_buffer_bytes() const {
    size_t largest = 0;
#define WF_LARGEST(type, name, what) largest = std::max(largest, name.size() * sizeof(type));
    WF_SCENE_BUFFERS(WF_LARGEST)
#undef WF_LARGEST
    return largest;
}

DeviceScene upload_scene(const cl::Context& context, const DeviceSceneData& data) {
    DeviceScene s;
#define WF_UPLOAD(type, name, what) s.name = upload_read_only(context, data.name, s.bytes);
    WF_SCENE_BUFFERS(WF_UPLOAD)
#undef WF_UPLOAD
    s.environment = data.environment;
    s.light_count = static_cast<uint32_t>(data.lights.size());
    s.environment_light = data.environment_light;
    s.scene_diameter = data.scene_diameter;
    return s;
}

} // namespace wf
