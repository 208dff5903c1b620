/* texture.h — texture lookups, shared by the kernels and the host (which
 * compiles it to test it and to agree with the device).
 *
 * Owns: texture_sample(), which reads one texture of the scene's texture set
 * (include/wavefront/scene_types.h: TextureInfo, TextureRef) at a texture
 * coordinate, and the pieces it is made of.
 *
 * Promises:
 * - the TextureRef's KHR_texture_transform is applied to uv first;
 * - texel (i, j) has its centre at ((i + 0.5) / width, (j + 0.5) / height),
 *   v running down the image (glTF's convention: uv (0, 0) is the top-left
 *   corner of the first texel);
 * - bilinear filtering between the four nearest texel centres, or the one
 *   nearest texel when the sampler's magFilter is NEAREST; no mipmaps;
 * - the sampler's wrap modes REPEAT, CLAMP_TO_EDGE and MIRRORED_REPEAT, per
 *   axis, evaluated in float on the reduced coordinate, so any finite uv is
 *   safe (no integer overflow); a NaN or infinite coordinate reads as 0;
 * - sRGB textures (base colour, emissive) are decoded to linear per texel,
 *   before filtering, so the filter averages light, not encoded values; alpha
 *   is always linear;
 * - a TextureRef without a texture (texture < 0) reads as (1, 1, 1, 1), the
 *   neutral value for the factors it multiplies; the normal map's caller must
 *   test texture >= 0 itself;
 * - the result is finite, each channel in [0, 1].
 * Texels are RGBA8 (4 bytes each); sRGB channels are decoded by a 256-entry
 * table (materials/srgb_table.h), three lookups per texel read. */
#ifndef WF_TEXTURE_H
#define WF_TEXTURE_H

#include "wavefront/compat.h"
#include "wavefront/scene_types.h"
#include "materials/srgb_table.h"

WF_DEVICE_BEGIN

/* The texture coordinate set a TextureRef asks for. */
WF_INLINE float2 texture_pick_uv(WF_GLOBAL const TextureRef* ref, float2 uv0, float2 uv1) {
    return ref->texcoord == 1u ? uv1 : uv0;
}

/* KHR_texture_transform's affine map; NaN and Inf become 0 here, before any
 * wrapping. */
WF_INLINE float2 texture_transform_uv(WF_GLOBAL const TextureRef* ref, float2 uv) {
    const float u = ref->transform[0] * uv.x + ref->transform[1] * uv.y + ref->transform[2];
    const float v = ref->transform[3] * uv.x + ref->transform[4] * uv.y + ref->transform[5];
    const bool u_finite = (as_uint(u) & 0x7f800000u) != 0x7f800000u;
    const bool v_finite = (as_uint(v) & 0x7f800000u) != 0x7f800000u;
    return make_float2(u_finite ? u : 0.0f, v_finite ? v : 0.0f);
}

/* A finite coordinate reduced to one period of the wrap mode, in texels:
 * REPEAT to [0, size], MIRRORED_REPEAT to [0, 2 size], CLAMP_TO_EDGE to
 * [0, size]. The bounds are inclusive because u - floor(u) may round to 1. */
WF_INLINE float texture_reduce(float u, uint32_t wrap, uint32_t size) {
    float reduced;
    if (wrap == WF_WRAP_CLAMP_TO_EDGE)
        reduced = u < 0.0f ? 0.0f : (u > 1.0f ? 1.0f : u);
    else if (wrap == WF_WRAP_MIRRORED_REPEAT)
        reduced = u - 2.0f * floor(0.5f * u);
    else
        reduced = u - floor(u);
    return reduced * (float)size;
}

/* Texel index i (in [-1, 2 size], what texture_reduce allows) wrapped into
 * [0, size). */
WF_INLINE uint32_t texture_wrap_index(int32_t i, uint32_t wrap, uint32_t size) {
    const int32_t n = (int32_t)size;
    if (wrap == WF_WRAP_CLAMP_TO_EDGE) return (uint32_t)(i < 0 ? 0 : (i >= n ? n - 1 : i));
    if (wrap == WF_WRAP_MIRRORED_REPEAT) {
        int32_t m = i < 0 ? i + 2 * n : (i >= 2 * n ? i - 2 * n : i); /* [0, 2n) */
        return (uint32_t)(m < n ? m : 2 * n - 1 - m);
    }
    return (uint32_t)(i < 0 ? i + n : (i >= n ? i - n : i));
}

/* One texel as linear RGBA in [0, 1]. */
WF_INLINE float4 texture_texel(WF_GLOBAL const TextureInfo* info, WF_GLOBAL const uint32_t* texels,
                               uint32_t x, uint32_t y) {
    const uint32_t bits = texels[info->offset + (y * info->width + x) * info->stride];
    const float4 c = make_float4((float)(bits & 0xffu), (float)((bits >> 8) & 0xffu),
                                 (float)((bits >> 16) & 0xffu), (float)(bits >> 24)) *
                     (1.0f / 255.0f);
    if (info->flags & WF_TEXTURE_SRGB)
        return make_float4(srgb_to_linear_table[bits & 0xffu], srgb_to_linear_table[(bits >> 8) & 0xffu],
                           srgb_to_linear_table[(bits >> 16) & 0xffu], c.w);
    return c;
}

/* The texture `ref` names at texture coordinate `uv` (the set ref->texcoord
 * asks for: texture_pick_uv), as linear RGBA. */
WF_INLINE float4 texture_sample(WF_GLOBAL const TextureInfo* infos, WF_GLOBAL const uint32_t* texels,
                                WF_GLOBAL const TextureRef* ref, float2 uv) {
    if (ref->texture < 0) return make_float4(1.0f, 1.0f, 1.0f, 1.0f);
    WF_GLOBAL const TextureInfo* info = infos + ref->texture;
    const float2 st = texture_transform_uv(ref, uv);
    const float x = texture_reduce(st.x, info->wrap_s, info->width);
    const float y = texture_reduce(st.y, info->wrap_t, info->height);
    if (info->flags & WF_TEXTURE_NEAREST) {
        return texture_texel(info, texels, texture_wrap_index((int32_t)floor(x), info->wrap_s, info->width),
                             texture_wrap_index((int32_t)floor(y), info->wrap_t, info->height));
    }
    /* Texel centres sit at half-integers: the four around (x, y) start at
     * floor(x - 0.5), in [-1, 2 size]. */
    const float fx = floor(x - 0.5f), fy = floor(y - 0.5f);
    const float tx = (x - 0.5f) - fx, ty = (y - 0.5f) - fy;
    const uint32_t x0 = texture_wrap_index((int32_t)fx, info->wrap_s, info->width);
    const uint32_t x1 = texture_wrap_index((int32_t)fx + 1, info->wrap_s, info->width);
    const uint32_t y0 = texture_wrap_index((int32_t)fy, info->wrap_t, info->height);
    const uint32_t y1 = texture_wrap_index((int32_t)fy + 1, info->wrap_t, info->height);
    const float4 top = texture_texel(info, texels, x0, y0) * (1.0f - tx) + texture_texel(info, texels, x1, y0) * tx;
    const float4 bottom = texture_texel(info, texels, x0, y1) * (1.0f - tx) + texture_texel(info, texels, x1, y1) * tx;
    return top * (1.0f - ty) + bottom * ty;
}

WF_DEVICE_END

#endif /* WF_TEXTURE_H */
