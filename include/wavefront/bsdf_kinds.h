/* bsdf_kinds.h — the BSDF kinds: each a set of lobes, shaded by code of its
 * own written once for any lane width, so that the group schedule shades it
 * eight or sixteen paths a work-item. The host gives every material one
 * (host/device/bsdf_kind_choice.cpp) and the program compiles only the kinds
 * the scene has (WF_HAS_BSDF_<KIND>). Today one kind takes every material, so
 * shade calls its core without a dispatch (kernels/bsdf/kinds.h): its lobes
 * are compiled where the scene has them (scene features), and lanes skip
 * those no lane of a run needs. The general BSDF (bsdf/bsdf.h), every lobe behind
 * branches, is not a kind but the oracle each kind is tested against.
 *   X(KIND, "name", what-it-holds) */
#ifndef WAVEFRONT_BSDF_KINDS_H
#define WAVEFRONT_BSDF_KINDS_H

#define WF_BSDF_KINDS(X)                                                                                     \
    X(LAYERED, "layered",                                                                                    \
      "a diffuse base under a GGX dielectric or metal interface that may transmit, and a sheen and a clear " \
      "coat over them where the material has them (bsdf/kinds/layered.inc)")

#define WF_BSDF_KIND_ENUM(kind, name, what) WF_BSDF_##kind,
enum BsdfKind { WF_BSDF_KINDS(WF_BSDF_KIND_ENUM) WF_BSDF_KIND_COUNT };
#undef WF_BSDF_KIND_ENUM

#endif
