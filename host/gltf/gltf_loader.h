// gltf_loader.h — reads a glTF 2.0 file (.gltf or .glb) into a wf::Scene:
// every triangle of the default scene in world space with its shading normals
// and material, the textures its materials use (gltf_textures.h), and the
// camera if one is asked for or present. Everything the renderer cannot use
// yet (points, lines, unknown extensions) is skipped with a warning in Scene::warnings; everything it cannot trust
// (bad JSON, short buffers, non-finite positions, stray indices) is an
// InputError whose one-line message names the file and, where one is at
// fault, the mesh.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace wf {

struct LoadOptions {
    int camera_index = -1; // -1: the first perspective camera in the file, if any
    // A mesh that several nodes place is kept once and placed by instances
    // (Scene::shared_meshes); false writes every placement out in world space.
    bool instancing = true;
};

// Loads a .gltf or .glb. Throws InputError with a one-line message that names
// the file (and the mesh, where one is at fault).
Scene load_gltf(const std::string& path, const LoadOptions& options = {});

// The same from the file's bytes, already read (the fuzz target feeds them
// without a file). `path` names the file in messages, and its folder is where
// external buffers and images are looked for.
Scene load_gltf_bytes(const std::string& path, const std::vector<unsigned char>& bytes,
                      const LoadOptions& options = {});

} // namespace wf
