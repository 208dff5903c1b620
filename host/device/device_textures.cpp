// device_textures.cpp — flattening the materials' texture fields, and upload.
#include "device/device_textures.h"

#include "device/device_buffer.h"

namespace wf {

size_t DeviceTextureData::bytes() const {
    return infos.size() * sizeof(TextureInfo) + texels.size() * sizeof(uint32_t) +
           refs.size() * sizeof(TextureRef) + params.size() * sizeof(MaterialTextureParams) +
           texcoords.size() * sizeof(TriangleTexcoords) + tangents.size() * sizeof(TriangleTangents);
}

DeviceTextureData make_device_texture_data(const Scene& scene, const std::vector<uint32_t>& triangle_order) {
    DeviceTextureData d;
    // Coordinates a scene lacks (a primitive without TEXCOORD_n) read as (0, 0).
    const bool textured = !scene.textures.infos.empty();
    if (textured) {
        const auto corner_uv = [&](const std::vector<glm::vec2>& uv, size_t corner, float* out) {
            const glm::vec2 v = uv.size() > corner ? uv[corner] : glm::vec2(0.0f);
            out[0] = v.x;
            out[1] = v.y;
        };
        for (const uint32_t t : triangle_order) {
            TriangleTexcoords tc{};
            TriangleTangents tg{};
            float* tangents[3] = {tg.t0, tg.t1, tg.t2};
            for (size_t k = 0; k < 3; ++k) {
                corner_uv(scene.uv0, 3 * t + k, tc.uv0 + 2 * k);
                corner_uv(scene.uv1, 3 * t + k, tc.uv1 + 2 * k);
                const glm::vec4 tangent = scene.tangents.size() > 3 * t + k ? scene.tangents[3 * t + k]
                                                                             : glm::vec4(1, 0, 0, 1);
                for (int c = 0; c < 4; ++c) tangents[k][c] = tangent[c];
            }
            d.texcoords.push_back(tc);
            d.tangents.push_back(tg);
        }
    }
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
    t.infos = upload_read_only(context, data.infos, t.bytes);
    t.texels = upload_read_only(context, data.texels, t.bytes);
    t.refs = upload_read_only(context, data.refs, t.bytes);
    t.params = upload_read_only(context, data.params, t.bytes);
    t.texcoords = upload_read_only(context, data.texcoords, t.bytes);
    t.tangents = upload_read_only(context, data.tangents, t.bytes);
    return t;
}

cl_uint set_texture_args(cl::Kernel& kernel, cl_uint first, const DeviceTextures& t) {
    for (const cl::Buffer* buffer : {&t.infos, &t.texels, &t.refs, &t.params, &t.texcoords, &t.tangents})
        kernel.setArg(first++, *buffer);
    return first;
}

} // namespace wf
