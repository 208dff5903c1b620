// device_textures.cpp — the texture part of the device scene
// (add_texture_data in device_scene.h): each material's texture references
// and parameters flattened in material order, and per-triangle texture
// coordinates and tangents in BVH order, only for scenes with textures, and
// per-triangle vertex colours, only for scenes whose colours are not all white.
#include "device/device_scene.h"
#include "device/texel_interleave.h"

namespace wf {

void add_texture_data(const Scene& scene, const std::vector<uint32_t>& triangle_order, DeviceSceneData& d) {
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
            if (t == kNoTriangle) { // a lane no leaf uses: never read
                d.texcoords.push_back(tc);
                d.tangents.push_back(tg);
                continue;
            }
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
    if (scene.has_vertex_colors())
        for (const uint32_t t : triangle_order) {
            TriangleColors c{};
            if (t == kNoTriangle) {
                d.colors.push_back(c);
                continue;
            }
            float* corners[3] = {c.c0, c.c1, c.c2};
            for (size_t k = 0; k < 3; ++k)
                for (int i = 0; i < 4; ++i) corners[k][i] = scene.colors[3 * t + k][i];
            d.colors.push_back(c);
        }
    InterleavedTexels interleaved = interleave_texels(scene);
    d.texture_infos = std::move(interleaved.infos);
    d.texels = std::move(interleaved.texels);
    for (const SceneMaterial& m : scene.materials) {
        d.texture_refs.insert(d.texture_refs.end(), m.textures.begin(), m.textures.end());
        MaterialTextureParams p{};
        p.normal_scale = m.normal_scale;
        p.alpha_mode = m.alpha_mode;
        p.alpha_cutoff = m.alpha_cutoff;
        p.base_alpha = m.base_alpha;
        d.material_textures.push_back(p);
    }
}

} // namespace wf
