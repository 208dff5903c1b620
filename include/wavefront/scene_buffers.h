/* scene_buffers.h — every buffer of the scene that the kernels read, declared
 * once, as Cycles declares its data arrays (kernel/data_arrays.h).
 *
 * The list expands into the kernels' parameters and the Scene they gather
 * them into (kernels/kernel_params.h), the host's vectors and buffers of the
 * device scene with their upload (host/device/device_scene.h), and the loop
 * that binds them to every kernel (host/integrator/stage_args.cpp). Nothing
 * passes a scene buffer by position, so none can be swapped or left out.
 *   X(element type, name, what it holds) */
#ifndef WAVEFRONT_SCENE_BUFFERS_H
#define WAVEFRONT_SCENE_BUFFERS_H

#include "wavefront/scene_types.h"

#define WF_SCENE_BUFFERS(X)                                                                           \
    X(BvhNode, nodes, "the 8-wide BVH; node 0 holds the scene's box")                                 \
    X(Instance, instances, "a two-level BVH's placements of shared meshes; empty without")           \
    X(TriangleBlock, triangles, "corners, light entry and material, four triangles a block, in BVH order")\
    X(TriangleNormals, normals, "shading normals per corner, in BVH order")                           \
    X(Material, materials, "glTF factors, one per material")                                          \
    X(LightEntry, lights, "every light of positive power, as an alias table by power")                \
    X(PunctualLight, punctual, "KHR_lights_punctual lights, in world space")                          \
    X(float, environment_texels, "the environment: RGB radiance and solid-angle pdf per texel")       \
    X(float, environment_distribution, "its marginal CDF, then one CDF per row")                      \
    X(TextureInfo, texture_infos, "where each texture's texels start, its size and sampler")          \
    X(uint32_t, texels, "every texture's texels, RGBA8")                                              \
    X(TextureRef, texture_refs, "WF_TEXTURE_SLOTS per material")                                      \
    X(MaterialTextureParams, material_textures, "normal scale and alpha mode, one per material")      \
    X(TriangleTexcoords, texcoords, "per triangle in BVH order; empty without textures")              \
    X(TriangleTangents, tangents, "per triangle in BVH order; empty without textures")                \
    X(TriangleColors, colors, "COLOR_0 per triangle in BVH order; empty where all are white")            \
    X(float, glass_albedo, "bsdf/albedo_tables.h's glass table, for GPUs (WF_GLASS_TABLE_IN_SCENE)")

#endif /* WAVEFRONT_SCENE_BUFFERS_H */
