// device_scene.h — the scene in the layout the kernels read
// (include/wavefront/scene_types.h): triangles and normals in BVH order, the
// BVH, the materials and the table of emitters by power; and its upload.
#pragma once

#include <cstdint>
#include <vector>

#include <CL/opencl.hpp>

#include "bvh_builder.h"
#include "scene.h"
#include "wavefront/scene_types.h"

namespace wf {

struct DeviceSceneData {
    std::vector<BvhNode> nodes;
    std::vector<Triangle> triangles;
    std::vector<TriangleNormals> normals;
    std::vector<Material> materials;
    std::vector<LightEntry> lights; // emissive triangles of positive power
    double emitted_power = 0.0;     // W, summed over the three channels' mean

    size_t bytes() const;                // device memory the buffers will take
    size_t largest_buffer_bytes() const; // the largest single allocation among them
};

DeviceSceneData make_device_scene_data(const Scene& scene, const Bvh& bvh);

struct DeviceScene {
    cl::Buffer nodes, triangles, normals, materials, lights;
    uint32_t light_count = 0;
    size_t bytes = 0; // device memory held by the buffers above
};

DeviceScene upload_scene(const cl::Context& context, const DeviceSceneData& data);

} // namespace wf
