/* layout_fields.h — the list of shared structs and members whose size and
 * offset the host compares with the device compiler's at start-up
 * (host/device/layout_check.cpp, kernels/layout_probe.cl). A struct added to
 * scene_types.h or path_state.h is added here too. */
#ifndef WAVEFRONT_LAYOUT_FIELDS_H
#define WAVEFRONT_LAYOUT_FIELDS_H

#define WF_LAYOUT_STRUCTS(X) \
    X(BvhNode) X(TriangleBlock) X(TriangleNormals) X(Material) X(LightEntry) X(Camera) X(RenderParams) \
    X(Environment) X(PunctualLight) X(TextureInfo) X(TextureRef) X(MaterialTextureParams)  \
    X(TriangleTexcoords) X(TriangleTangents) X(TriangleColors) X(Instance)

#define WF_LAYOUT_MEMBERS(X)                                                                     \
    X(BvhNode, bounds) X(BvhNode, child)                                                           \
    X(Instance, object_to_world) X(Instance, world_to_object) X(Instance, root) X(Instance, handedness) \
    X(Instance, error_scale) X(Instance, pad)                                                        \
    X(TriangleBlock, corners) X(TriangleBlock, light) X(TriangleBlock, material) X(TriangleBlock, pad) \
    X(TriangleNormals, n0) X(TriangleNormals, n1) X(TriangleNormals, n2)                          \
    X(TriangleTexcoords, uv0) X(TriangleTexcoords, uv1)                                           \
    X(TriangleTangents, t0) X(TriangleTangents, t1) X(TriangleTangents, t2)                       \
    X(TriangleColors, c0) X(TriangleColors, c1) X(TriangleColors, c2)                             \
    X(Material, base_color) X(Material, flags) X(Material, emission) X(Material, metallic)       \
    X(Material, roughness) X(Material, transmission) X(Material, ior) X(Material, specular)        \
    X(Material, specular_color) X(Material, clearcoat) X(Material, clearcoat_roughness)           \
    X(Material, sheen_color) X(Material, sheen_roughness) X(Material, thin_walled)                 \
    X(LightEntry, probability) X(LightEntry, alias) X(LightEntry, index) X(LightEntry, pmf)       \
    X(LightEntry, kind)                                                                           \
    X(Camera, origin) X(Camera, tan_half_fov_y) X(Camera, right) X(Camera, aspect) X(Camera, up)  \
    X(Camera, width) X(Camera, forward) X(Camera, height)                                         \
    X(RenderParams, pixel_count) X(RenderParams, first_pixel) X(RenderParams, traced_pixels)     \
    X(RenderParams, pixel_list) X(RenderParams, pool_size) X(RenderParams, spp)                   \
    X(RenderParams, max_depth) X(RenderParams, seed) X(RenderParams, roulette_depth)              \
    X(RenderParams, roulette_cap)                                                                 \
    X(RenderParams, light_count) X(RenderParams, light_sampling) X(RenderParams, hemisphere)           \
    X(RenderParams, sampler) X(RenderParams, bounce_layers) X(RenderParams, environment_light)     \
    X(RenderParams, scene_diameter) X(RenderParams, aovs) X(RenderParams, environment)            \
    X(Environment, scale) X(Environment, flags) X(Environment, cos_rotation)                      \
    X(Environment, sin_rotation) X(Environment, width) X(Environment, height)                     \
    X(PunctualLight, position) X(PunctualLight, type) X(PunctualLight, direction)                 \
    X(PunctualLight, range) X(PunctualLight, intensity) X(PunctualLight, cos_outer)               \
    X(PunctualLight, cos_inner)                                                                   \
    X(TextureInfo, offset) X(TextureInfo, width) X(TextureInfo, height) X(TextureInfo, flags)     \
    X(TextureInfo, wrap_s) X(TextureInfo, wrap_t) X(TextureInfo, channels) X(TextureInfo, stride) \
    X(TextureRef, texture) X(TextureRef, texcoord) X(TextureRef, transform)                       \
    X(MaterialTextureParams, normal_scale) X(MaterialTextureParams, alpha_mode)                   \
    X(MaterialTextureParams, alpha_cutoff) X(MaterialTextureParams, base_alpha)

#endif /* WAVEFRONT_LAYOUT_FIELDS_H */
