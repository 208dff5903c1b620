// device_textures.cpp — flattening the materials' texture fields, and upload.
#include "device_textures.h"

namespace wf {
namespace {

template <class T> cl::Buffer upload(const cl::Context& context, const std::vector<T>& data, size_t& bytes) {
    // OpenCL has no empty buffers; an unused one holds a single zeroed element.
    std::vector<T> storage = data.empty() ? std::vector<T>(1, T{}) : data;
    bytes += storage.size() * sizeof(T);
    return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, storage.size() * sizeof(T),
                      storage.data());
}

} // namespace

size_t DeviceTextureData::bytes() const {
    return infos.size() * sizeof(TextureInfo) + texels.size() * sizeof(uint32_t) +
           refs.size() * sizeof(TextureRef) + params.size() * sizeof(MaterialTextureParams);
}

DeviceTextureData make_device_texture_data(const Scene& scene) {
    DeviceTextureData d;
    d.infos = scene.textures.infos;
    d.texels = scene.textures.texels;
    for (const SceneMaterial& m : scene.materials) {
        d.refs.insert(d.refs.end(), m.textures.begin(), m.textures.end());
        MaterialTextureParams p{};
        p.normal_scale = m.normal_scale;
        p.alpha_mode = m.alpha_mode;
        p.alpha_cutoff = m.alpha_cutoff;
        p.base_alpha = m.base_alpha;
        d.params.push_back(p);
    }
    return d;
}

DeviceTextures upload_textures(const cl::Context& context, const DeviceTextureData& data) {
    DeviceTextures t;
    t.infos = upload(context, data.infos, t.bytes);
    t.texels = upload(context, data.texels, t.bytes);
    t.refs = upload(context, data.refs, t.bytes);
    t.params = upload(context, data.params, t.bytes);
    return t;
}

} // namespace wf
