/* compiled_features.h — the scene features the program is compiled for. The host sets
 * each with -D from the scene (host/device/scene_features.h); a build without them,
 * such as the tests' own small programs, has every feature on. */
#ifndef WF_COMPILED_FEATURES_H
#define WF_COMPILED_FEATURES_H

#ifndef WF_HAS_TEXTURES
#define WF_HAS_TEXTURES 1
#endif
#ifndef WF_HAS_NORMAL_MAPS
#define WF_HAS_NORMAL_MAPS 1
#endif
#ifndef WF_HAS_ALPHA_MASK
#define WF_HAS_ALPHA_MASK 1
#endif
#ifndef WF_HAS_VERTEX_COLORS
#define WF_HAS_VERTEX_COLORS 1
#endif
#ifndef WF_HAS_EMISSIVE_TRIANGLES
#define WF_HAS_EMISSIVE_TRIANGLES 1
#endif
#ifndef WF_HAS_PUNCTUAL_LIGHTS
#define WF_HAS_PUNCTUAL_LIGHTS 1
#endif
#ifndef WF_HAS_ENVIRONMENT
#define WF_HAS_ENVIRONMENT 1
#endif
/* The BSDF kind's lobes beyond the diffuse base (bsdf/kinds/layered.inc,
 * bsdf/lobes/): its interface's reflection (a metal, a dielectric layer
 * whose KHR_materials_specular factor is above 0, or a material that
 * transmits through it), KHR_materials_transmission, KHR_materials_clearcoat
 * and KHR_materials_sheen. The general BSDF (bsdf/bsdf.h) also leaves out the
 * clear coat and sheen where theirs is 0. */
#ifndef WF_HAS_SPECULAR
#define WF_HAS_SPECULAR 1
#endif
#ifndef WF_HAS_TRANSMISSION
#define WF_HAS_TRANSMISSION 1
#endif
#ifndef WF_HAS_CLEARCOAT
#define WF_HAS_CLEARCOAT 1
#endif
#ifndef WF_HAS_SHEEN
#define WF_HAS_SHEEN 1
#endif
#if WF_HAS_TRANSMISSION && !WF_HAS_SPECULAR
#error "transmission goes through the interface: WF_HAS_TRANSMISSION needs WF_HAS_SPECULAR"
#endif
/* Shared meshes placed by instances: a two-level BVH (host/bvh/instance_bvh.h).
 * Not a feature the generic program may have on, but the layout of the
 * scene's buffers, so the host sets it from the scene always, and a build
 * without it has one level. */
#ifndef WF_HAS_INSTANCES
#define WF_HAS_INSTANCES 0
#endif
/* The BSDF kinds (wavefront/bsdf_kinds.h): WF_HAS_BSDF_<KIND>. */
#ifndef WF_HAS_BSDF_LAYERED
#define WF_HAS_BSDF_LAYERED 1
#endif

#endif
