/* scene_types.h — the scene as the device sees it: every struct in a buffer that
 * both the host writes and the kernels read.
 *
 * Layout rules (so OpenCL C and C++ agree without packing pragmas): only 4-byte
 * scalars and arrays of them, every struct a multiple of 16 bytes. The host
 * checks sizeof and offsetof of each against the device compiler at start-up
 * (host/device/layout_check.cpp), so a change here cannot silently drift. */
#ifndef WAVEFRONT_SCENE_TYPES_H
#define WAVEFRONT_SCENE_TYPES_H

#include "wavefront/compat.h"

/* 8-wide BVH node (host/bvh/bvh_builder.h, kernels/geometry/bvh_traverse.h): the
 * boxes of up to eight children, one lane each, so that one ray meets all
 * eight with float8 arithmetic. bounds rows: lower x, upper x, lower y, upper
 * y, lower z, upper z. An unused slot has an empty box (lower +inf, upper
 * -inf), which no ray meets, and a child word of 0. A child word is an
 * interior node's index (never 0: node 0 is no one's child), or for a leaf
 * WF_BVH_LEAF | (count - 1) << WF_BVH_COUNT_SHIFT | first: the triangles at
 * BVH positions [first, first + count), count from 1 to 8. A leaf of four or
 * more starts a TriangleBlock; a smaller one lies within one. */
#define WF_BVH_WIDTH 8
#define WF_BVH_LEAF 0x80000000u
#define WF_BVH_COUNT_SHIFT 28
#define WF_BVH_FIRST_MASK 0x0fffffffu
typedef struct BvhNode {
    float bounds[6][WF_BVH_WIDTH];
    uint32_t child[WF_BVH_WIDTH];
} BvhNode;

/* A placement of a shared mesh (host/bvh/instance_bvh.h). In a two-level
 * tree, node 0 holds the box of every placement over the top tree, whose
 * leaves hold one placement each, entry `first` of this buffer; each
 * placement's `root` holds its mesh's box over that mesh's own tree, as node 0
 * holds the scene's, in the mesh's space. The maps are 3x4 matrices, row r
 * giving coordinate r as m[r][0] x + m[r][1] y + m[r][2] z + m[r][3]. */
typedef struct Instance {
    float object_to_world[3][4];
    float world_to_object[3][4];
    uint32_t root;
    float handedness;  /* -1 where the map mirrors: a tangent's w times this; else 1 */
    float error_scale; /* what map_point_error scales its bound by: the way back's rounding (geometry/instance_map.h) */
    uint32_t pad;
} Instance;

/* Four triangles side by side, BVH positions 4b to 4b + 3 in block b, a lane
 * each (kernels/geometry/triangle_blocks.h reads one triangle back). corners
 * row 3c + axis holds corner c's x, y or z of the four, so a ray's leaf test
 * loads its permuted corners as nine float4 rows, as the node test loads its
 * boxes. Then what a hit needs next. 192 bytes: three cache lines. A lane no
 * leaf uses repeats lane 0's corners, has light -1, and is never reported. */
#define WF_BLOCK_LANES 4
typedef struct TriangleBlock {
    float corners[9][WF_BLOCK_LANES];
    int32_t light[WF_BLOCK_LANES]; /* index into the light table, or -1 when not emissive */
    uint32_t material[WF_BLOCK_LANES];
    uint32_t pad[WF_BLOCK_LANES]; /* to three whole cache lines */
} TriangleBlock;

/* Per-corner shading normals (the geometric normal where the file has none). */
typedef struct TriangleNormals {
    float n0[3];
    float pad0;
    float n1[3];
    float pad1;
    float n2[3];
    float pad2;
} TriangleNormals;

/* Per-corner texture coordinates and tangents, in BVH order beside the
 * triangle blocks; only scenes with textures upload them. A tangent's w is the
 * handedness: bitangent = cross(n, t) w. */
typedef struct TriangleTexcoords {
    float uv0[6]; /* TEXCOORD_0 of corners 0, 1, 2 */
    float uv1[6]; /* TEXCOORD_1 */
} TriangleTexcoords;

typedef struct TriangleTangents {
    float t0[4];
    float t1[4];
    float t2[4];
} TriangleTangents;

/* Per-corner COLOR_0 (linear RGBA), in BVH order beside the triangle blocks;
 * only scenes whose vertex colours are not all white upload them. */
typedef struct TriangleColors {
    float c0[4];
    float c1[4];
    float c2[4];
} TriangleColors;

#define WF_MATERIAL_DOUBLE_SIDED 1u /* emits from both faces */
#define WF_MATERIAL_VERTEX_COLORS 4u /* its triangles' COLOR_0 is in the colors buffer */

/* glTF 2.0 metallic-roughness, with KHR_materials_transmission, _ior,
 * _specular, _clearcoat and _sheen; kernels/bsdf/ says what each factor does
 * to the BSDF. */
typedef struct Material {
    float base_color[3]; /* linear, in [0, 1] */
    uint32_t flags;      /* WF_MATERIAL_* */
    float emission[3];   /* radiance Le, W sr^-1 m^-2, from the front face */
    float metallic;      /* in [0, 1] */
    float roughness;     /* perceptual, in [0, 1]; GGX alpha = roughness^2 */
    float transmission;  /* in [0, 1] */
    float ior;           /* index of refraction inside, >= 1 */
    float specular;      /* in [0, 1]; 0 leaves a plain Lambertian surface */
    float specular_color[3]; /* KHR_materials_specular's specularColorFactor, in [0, inf) */
    float clearcoat;           /* KHR_materials_clearcoat's factor, in [0, 1]; 0: no coat */
    float clearcoat_roughness; /* in [0, 1] */
    float sheen_color[3];      /* KHR_materials_sheen's sheenColorFactor, in [0, 1]; black: no sheen */
    float sheen_roughness;     /* in [0, 1] */
    float thin_walled;         /* 1: transmission without KHR_materials_volume, a sheet with no inside; 0: a solid */
    uint32_t pad[2];
} Material;

/* A texture as the kernels sample it (kernels/materials/texture.h). Texels
 * are RGBA8 packed in one uint32 each (R in the low byte), rows from the top
 * of the image down, `width * height` of them from `offset` in the scene's one
 * texel buffer, `stride` apart. Several TextureInfos may share texels (one
 * image under two samplers or colour spaces). */
#define WF_TEXTURE_SRGB 1u    /* RGB are sRGB-encoded: decoded per texel before filtering */
#define WF_TEXTURE_NEAREST 2u /* the sampler's magFilter is NEAREST: no bilinear filtering */

#define WF_WRAP_REPEAT 10497u /* glTF sampler wrap modes, with glTF's (GL's) numbers */
#define WF_WRAP_CLAMP_TO_EDGE 33071u
#define WF_WRAP_MIRRORED_REPEAT 33648u

typedef struct TextureInfo {
    uint32_t offset;   /* first texel in the texel buffer */
    uint32_t width;    /* >= 1 */
    uint32_t height;   /* >= 1 */
    uint32_t flags;    /* WF_TEXTURE_* */
    uint32_t wrap_s;   /* WF_WRAP_*, along u (image x) */
    uint32_t wrap_t;   /* WF_WRAP_*, along v (image y, down) */
    uint32_t channels; /* the source image's: 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA */
    uint32_t stride;   /* texels from one of the image's texels to the next: 1, or the number of
                          images interleaved with it (host/device/texel_interleave.h) */
} TextureInfo;

/* How a material reads one texture: which one, with which texture coordinate
 * set, through KHR_texture_transform's affine map, applied first:
 *   u' = transform[0] u + transform[1] v + transform[2]
 *   v' = transform[3] u + transform[4] v + transform[5] */
typedef struct TextureRef {
    int32_t texture;   /* index into the TextureInfo buffer, or -1: no texture */
    uint32_t texcoord; /* 0: TEXCOORD_0, 1: TEXCOORD_1 */
    float transform[6];
} TextureRef;

/* The texture slots of a material: the TextureRef buffer holds
 * WF_TEXTURE_SLOTS entries per material, material * WF_TEXTURE_SLOTS + slot. */
#define WF_TEXTURE_BASE_COLOR 0u         /* sRGB; RGB times base_color, A is alpha (linear) */
#define WF_TEXTURE_METALLIC_ROUGHNESS 1u /* linear; B times metallic, G times roughness */
#define WF_TEXTURE_NORMAL 2u             /* linear; tangent-space normal, 2 c - 1 */
#define WF_TEXTURE_EMISSIVE 3u           /* sRGB; RGB times emission */
#define WF_TEXTURE_SPECULAR 4u           /* linear; A times specular (KHR_materials_specular) */
#define WF_TEXTURE_SPECULAR_COLOR 5u     /* sRGB; RGB times specular_color */
#define WF_TEXTURE_TRANSMISSION 6u       /* linear; R times transmission (KHR_materials_transmission) */
#define WF_TEXTURE_CLEARCOAT 7u          /* linear; R times clearcoat (KHR_materials_clearcoat) */
#define WF_TEXTURE_CLEARCOAT_ROUGHNESS 8u /* linear; G times clearcoat_roughness */
#define WF_TEXTURE_SHEEN_COLOR 9u        /* sRGB; RGB times sheen_color (KHR_materials_sheen) */
#define WF_TEXTURE_SHEEN_ROUGHNESS 10u   /* linear; A times sheen_roughness */
#define WF_TEXTURE_SLOTS 11u

#define WF_ALPHA_OPAQUE 0u /* alpha ignored */
#define WF_ALPHA_MASK 1u   /* surface absent where alpha < alpha_cutoff */

/* Per material, beside its TextureRefs: what modulates the sampled values. */
typedef struct MaterialTextureParams {
    float normal_scale;    /* glTF normalTexture.scale: scales the normal's x and y */
    uint32_t alpha_mode;   /* WF_ALPHA_*; glTF BLEND is loaded as MASK (host/gltf/gltf_textures.cpp) */
    float alpha_cutoff;    /* for WF_ALPHA_MASK */
    float base_alpha;      /* baseColorFactor's alpha, times the texture's */
} MaterialTextureParams;

/* The kinds of light next-event estimation chooses among. */
#define WF_LIGHT_TRIANGLE 0u    /* an emissive triangle */
#define WF_LIGHT_PUNCTUAL 1u    /* a KHR_lights_punctual light: a delta light */
#define WF_LIGHT_ENVIRONMENT 2u /* the environment, at most one */
#define WF_NO_LIGHT 0xffffffffu /* an index into the light table that names none */

/* One entry of the alias table over every light, chosen by power. */
typedef struct LightEntry {
    float probability; /* keep this entry with this probability, else take alias */
    uint32_t alias;
    uint32_t index;    /* a BVH position or a PunctualLight, by kind */
    float pmf;         /* probability that this entry's light is chosen */
    uint32_t kind;     /* WF_LIGHT_* */
    uint32_t pad[3];
} LightEntry;

/* A pinhole camera; pixel (0,0) is the top-left corner of the image. */
typedef struct Camera {
    float origin[3];
    float tan_half_fov_y;
    float right[3]; /* unit vectors */
    float aspect;   /* width / height */
    float up[3];
    uint32_t width;
    float forward[3];
    uint32_t height;
} Camera;

#define WF_ENVIRONMENT_CONSTANT 1u /* the same radiance, `scale`, from every direction */

/* Light from infinitely far away (kernels/lights/environment.h). A map of
 * width x height equirectangular texels, or with WF_ENVIRONMENT_CONSTANT a
 * constant radiance and no texels. Its two buffers (host/scene/environment_map.h):
 * texels, four floats per texel (RGB radiance before `scale`, then the
 * sampling density in solid angle), and the sampling distribution's CDFs. */
typedef struct Environment {
    float scale[3];     /* multiplies every texel; the radiance itself when constant */
    uint32_t flags;     /* WF_ENVIRONMENT_* */
    float cos_rotation; /* the map is turned about +y: world = R_y(rotation) map */
    float sin_rotation;
    uint32_t width;
    uint32_t height;
} Environment;

#define WF_PUNCTUAL_POINT 0u
#define WF_PUNCTUAL_SPOT 1u
#define WF_PUNCTUAL_DIRECTIONAL 2u

/* A glTF KHR_lights_punctual light (kernels/lights/punctual.h), a delta light.
 * glTF's photometric numbers are taken as radiometric ones: 1 cd as 1 W/sr
 * (point, spot), 1 lux as 1 W/m^2 (directional). */
typedef struct PunctualLight {
    float position[3];  /* world space; unused by a directional light */
    uint32_t type;      /* WF_PUNCTUAL_* */
    float direction[3]; /* unit: where a spot points, where directional light travels */
    float range;        /* glTF's range, 0 = unbounded; kept, not applied */
    float intensity[3]; /* colour x intensity: W/sr, or W/m^2 when directional */
    float cos_outer;    /* spot cone: cos of glTF's outerConeAngle */
    float cos_inner;    /* and of its innerConeAngle */
    float pad[3];
} PunctualLight;

#endif /* WAVEFRONT_SCENE_TYPES_H */
