// device_scene.h — the scene in the layout the kernels read: one vector per
// scene buffer of include/wavefront/scene_buffers.h (triangles and normals in
// BVH order, the BVH, materials, lights, environment, textures), the light
// table by power, and their upload, one cl::Buffer per vector.
//
// The members are generated from WF_SCENE_BUFFERS, so a buffer added to that
// list is sized, uploaded and bound (host/integrator/stage_args.cpp) without
// another edit. An empty vector uploads one zeroed element that no kernel
// reads, since OpenCL has no empty buffers (device_buffer.h).
#pragma once

#include <cstdint>
#include <vector>

#include <CL/opencl.hpp>

#include "bvh/bvh_builder.h"
#include "scene/scene.h"
#include "wavefront/scene_buffers.h"

namespace wf {

struct DeviceSceneData {
#define WF_SCENE_DATA_MEMBER(type, name, what) std::vector<type> name;
    WF_SCENE_BUFFERS(WF_SCENE_DATA_MEMBER)
#undef WF_SCENE_DATA_MEMBER
    Environment environment{};                // passed by value in the render constants
    uint32_t emissive_triangles = 0;          // the first entries of `lights`, in the scene's triangle order
    uint32_t environment_light = WF_NO_LIGHT; // its entry in `lights`
    float scene_diameter = 0.0f;              // of the triangles' bounds

    size_t bytes() const;                // device memory the buffers will take
    size_t largest_buffer_bytes() const; // the largest single allocation among them
    size_t traversal_bytes() const;      // the BVH nodes and the triangle blocks: what intersection reads
};

DeviceSceneData make_device_scene_data(const Scene& scene, const Bvh& bvh);

// The part of make_device_scene_data that flattens the materials' texture
// fields and the per-corner texture coordinates and tangents
// (device_textures.cpp). `triangle_order`: the scene's triangle index at each
// BVH position.
void add_texture_data(const Scene& scene, const std::vector<uint32_t>& triangle_order, DeviceSceneData& data);

struct DeviceScene {
#define WF_DEVICE_SCENE_MEMBER(type, name, what) cl::Buffer name;
    WF_SCENE_BUFFERS(WF_DEVICE_SCENE_MEMBER)
#undef WF_DEVICE_SCENE_MEMBER
    Environment environment{};
    uint32_t light_count = 0;
    uint32_t environment_light = WF_NO_LIGHT;
    float scene_diameter = 0.0f;
    size_t bytes = 0; // device memory held by the buffers above
};

DeviceScene upload_scene(const cl::Context& context, const DeviceSceneData& data);

} // namespace wf
