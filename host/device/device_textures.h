// device_textures.h — a scene's textures, its materials' texture references
// and its per-corner texture coordinates and tangents, as the kernels read
// them (kernels/materials/texture.h); and their upload. Part of the device
// scene (device_scene.h).
#pragma once

#include <vector>

#include <CL/opencl.hpp>

#include "scene/scene.h"
#include "wavefront/scene_types.h"

namespace wf {

struct DeviceTextureData {
    std::vector<TextureInfo> infos;
    std::vector<uint32_t> texels;                 // RGBA8
    std::vector<TextureRef> refs;                 // WF_TEXTURE_SLOTS per material, in material order
    std::vector<MaterialTextureParams> params;    // one per material
    std::vector<TriangleTexcoords> texcoords;     // per triangle in BVH order; empty without textures
    std::vector<TriangleTangents> tangents;       // likewise

    size_t bytes() const;
};

// `triangle_order`: the scene's triangle index at each BVH position.
DeviceTextureData make_device_texture_data(const Scene& scene, const std::vector<uint32_t>& triangle_order);

struct DeviceTextures {
    cl::Buffer infos, texels, refs, params, texcoords, tangents; // never empty (device_buffer.h)
    size_t bytes = 0;                       // device memory held by the buffers above
};

DeviceTextures upload_textures(const cl::Context& context, const DeviceTextureData& data);

// Sets the buffers as `kernel`'s arguments from index `first` on, in the order
// of WF_SCENE_TEXTURE_PARAMS (kernels/materials/surface_material.h); returns
// the index after them.
cl_uint set_texture_args(cl::Kernel& kernel, cl_uint first, const DeviceTextures& textures);

} // namespace wf
