// device_scene.h — the scene in the layout the kernels read
// (include/wavefront/scene_types.h): triangles and normals in BVH order, the
// BVH, the materials, the punctual lights, the environment, and the table of
// every light by power; and its upload.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <CL/opencl.hpp>

#include "bvh/bvh_builder.h"
#include "device/device_textures.h"
#include "scene/environment_map.h"
#include "scene/scene.h"
#include "wavefront/scene_types.h"

namespace wf {

struct DeviceSceneData {
    std::vector<BvhNode> nodes;
    std::vector<Triangle> triangles;
    std::vector<TriangleNormals> normals;
    std::vector<Material> materials;
    std::vector<PunctualLight> punctual;
    std::shared_ptr<const EnvironmentMap> environment;
    DeviceTextureData textures;
    std::vector<LightEntry> lights; // every light of positive power: triangles, punctual, environment
    uint32_t emissive_triangles = 0;
    uint32_t environment_light = WF_NO_LIGHT; // its entry in `lights`
    float scene_diameter = 0.0f;              // of the triangles' bounds
    double emitted_power = 0.0;               // W, summed over the three channels' mean

    size_t bytes() const;                // device memory the buffers will take
    size_t largest_buffer_bytes() const; // the largest single allocation among them
};

DeviceSceneData make_device_scene_data(const Scene& scene, const Bvh& bvh);

struct DeviceScene {
    cl::Buffer nodes, triangles, normals, materials, lights, punctual;
    DeviceEnvironment environment; // a one-element placeholder when the scene has none
    DeviceTextures textures;
    uint32_t light_count = 0;
    uint32_t environment_light = WF_NO_LIGHT;
    float scene_diameter = 0.0f;
    size_t bytes = 0; // device memory held by the buffers above
};

DeviceScene upload_scene(const cl::Context& context, const DeviceSceneData& data);

} // namespace wf
