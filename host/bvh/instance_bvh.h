// instance_bvh.h — the BVH of a scene with shared meshes (scene/scene.h): a
// tree per shared mesh in the mesh's own space, built once however many
// instances place it, and one for the world-space triangles, all under a top
// tree over their placements (Instance, include/wavefront/scene_types.h).
// Memory grows with the unique triangles, not the placed ones.
//
// Promises: node 0 holds the box of every placement over the top tree; the
// top tree's leaves hold one entry of `instances` each, each placement's `root` a node
// that holds its mesh's box over the top of the mesh's tree, as node 0 holds
// the scene's in a one-level tree (bvh_builder.h promises the rest of each
// tree); the meshes' trees follow the top tree, their BVH positions side by
// side in `order`, each tree's in whole blocks. A placement's box holds its
// mesh's box mapped, grown for the rounding of the ray mapped into the mesh's
// space (instance_bvh.cpp says how far that holds). A scene without shared meshes
// gets build_bvh's one-level tree, unchanged. Deterministic.
#pragma once

#include "bvh/bvh_builder.h"
#include "scene/scene.h"

namespace wf {

Bvh build_scene_bvh(const Scene& scene);

} // namespace wf
