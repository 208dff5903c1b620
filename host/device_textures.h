// device_textures.h — a scene's textures and its materials' texture
// references as the kernels read them (kernels/materials/texture.h), and
// their upload. Kept apart from device_scene.h so the two can be wired
// together by whoever adds texturing to the shading stages.
#pragma once

#include <vector>

#include <CL/opencl.hpp>

#include "scene.h"
#include "wavefront/scene_types.h"

namespace wf {

struct DeviceTextureData {
    std::vector<TextureInfo> infos;
    std::vector<uint32_t> texels;                 // RGBA8
    std::vector<TextureRef> refs;                 // WF_TEXTURE_SLOTS per material, in material order
    std::vector<MaterialTextureParams> params;    // one per material

    size_t bytes() const;
};

DeviceTextureData make_device_texture_data(const Scene& scene);

struct DeviceTextures {
    cl::Buffer infos, texels, refs, params; // never empty: an unused one holds one zeroed element
    size_t bytes = 0;                       // device memory held by the buffers above
};

DeviceTextures upload_textures(const cl::Context& context, const DeviceTextureData& data);

} // namespace wf
