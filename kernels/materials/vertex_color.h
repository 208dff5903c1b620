/* vertex_color.h — glTF's COLOR_0 at one point of one triangle: linear RGBA
 * that multiplies the base colour and its alpha (glTF 2.0 §3.7.2.1), read by
 * the shade stage's material (materials/surface_material.h) and the BVH's
 * alpha test (materials/alpha_mask.h). A scene whose colours are all white
 * uploads none and no material has WF_MATERIAL_VERTEX_COLORS: it reads
 * (1, 1, 1, 1), as a program compiled without WF_HAS_VERTEX_COLORS does.
 * Device only. */
#ifndef WF_VERTEX_COLOR_H
#define WF_VERTEX_COLOR_H

#include "wavefront/compat.h"
#include "compiled_features.h"
#include "scene_view.h"
#include "materials/surface_texture.h"

WF_INLINE float4 surface_vertex_color(const Scene* scene, const SurfacePoint* p) {
#if WF_HAS_VERTEX_COLORS
    if (!(scene->materials[p->material].flags & WF_MATERIAL_VERTEX_COLORS)) return (float4)(1.0f);
    __global const TriangleColors* c = &scene->colors[p->triangle];
    const float b0 = 1.0f - p->b1 - p->b2;
    return b0 * vload4(0, c->c0) + p->b1 * vload4(0, c->c1) + p->b2 * vload4(0, c->c2);
#else
    return (float4)(1.0f);
#endif
}

#endif
