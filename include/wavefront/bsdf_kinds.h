/* bsdf_kinds.h — the BSDF kinds: each a fixed set of lobes, shaded by code of
 * its own. The host gives every material one (host/device/bsdf_kind_choice.cpp),
 * the program compiles only the kinds the scene has (WF_HAS_BSDF_<KIND>), and
 * the shade stage dispatches on it (kernels/bsdf/kinds.h); the kinds other than
 * the general one are written once for any lane width, so the group schedule
 * shades them eight or sixteen paths a work-item.
 *   X(KIND, "name", what-it-holds) */
#ifndef WAVEFRONT_BSDF_KINDS_H
#define WAVEFRONT_BSDF_KINDS_H

#define WF_BSDF_KINDS(X)                                                                                     \
    X(GENERAL, "general", "every lobe of bsdf/bsdf.h behind branches: transmission, clear coat, sheen")      \
    X(OPAQUE, "opaque",                                                                                      \
      "a diffuse base under a GGX dielectric or metal interface, and a sheen and a clear coat over them "    \
      "where the material has them (bsdf/kinds/opaque.inc)")

#define WF_BSDF_KIND_ENUM(kind, name, what) WF_BSDF_##kind,
enum BsdfKind { WF_BSDF_KINDS(WF_BSDF_KIND_ENUM) WF_BSDF_KIND_COUNT };
#undef WF_BSDF_KIND_ENUM

#endif
