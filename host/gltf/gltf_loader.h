// gltf_loader.h — reads a glTF 2.0 file (.gltf or .glb) into a wf::Scene:
// every triangle of the default scene in world space with its shading normals
// and material, the textures its materials use (gltf_textures.h), and the
// camera if one is asked for or present. Everything the renderer cannot use
// yet (points, lines, unknown extensions) is skipped with a warning in Scene::warnings; everything it cannot trust
// (bad JSON, short buffers, non-finite positions, stray indices) is an
// InputError whose one-line message names the file and, where one is at
// fault, the mesh.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace wf {

// Which meshes that several nodes place are kept once and placed by
// instances (Scene::shared_meshes), the rest written out in world space at
// each placement: none; those whose copies beyond the first would hold
// kLargeSharedTriangles or more (a small mesh renders faster written out, its
// copies cheap: NegativeScaleTest's 3.9 K triangles, kept once, rendered
// 0.81-0.83x as fast, bench/results/ray-throughput.md); or all.
enum class Instancing { Off, Large, All };
constexpr std::array<const char*, 5> kInstancingNames = {"off", "large", "all", nullptr, nullptr};
constexpr size_t kLargeSharedTriangles = 65536;

struct LoadOptions {
    int camera_index = -1; // -1: the first perspective camera in the file, if any
    Instancing instancing = Instancing::Large;
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
