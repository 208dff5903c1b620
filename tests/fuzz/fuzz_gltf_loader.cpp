// fuzz_gltf_loader.cpp — libFuzzer target over the scene-loading path: the
// bytes of one .gltf or .glb through wf::load_gltf_bytes (tinygltf's parsing,
// the loader's checks, texture decoding), then the host-side steps a render
// takes on the loaded scene before anything reaches a device: unlit scenes
// given their default sky, the BVH, and the device layout with its light
// table. An InputError is the expected answer to a bad file; anything else
// that escapes (another exception, a sanitizer report, a hang) is a bug.
// Built by -DWF_FUZZ=ON with clang; run by scripts/fuzz.sh. The inputs are
// mutated by gltf_mutator.cpp: as JSON where they are glTF, else as bytes.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bvh/instance_bvh.h"
#include "device/device_scene.h"
#include "scene/environment_map.h"
#include "base/errors.h"
#include "gltf/gltf_loader.h"

namespace {

// The input's name in messages; its folder, made empty once per process, is
// where external buffers and images are looked for, so a URI finds nothing
// unless it climbs out, which the loader must refuse.
const std::string& scene_path() {
    static const std::string path = [] {
        std::string folder = (std::filesystem::temp_directory_path() / "wf-fuzz-XXXXXX").string();
        if (!mkdtemp(folder.data())) std::abort();
        return folder + "/input.gltf";
    }();
    return path;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        // Every mesh several nodes place kept once, however small, so that the
        // mutator's duplicated nodes and links reach the instancing paths.
        wf::Scene scene = wf::load_gltf_bytes(scene_path(), std::vector<unsigned char>(data, data + size),
                                              wf::LoadOptions{-1, wf::Instancing::All});
        wf::light_unlit_scene(scene);
        // load_gltf promises at least one triangle with finite corners, and
        // placements it can invert, which is what build_scene_bvh requires;
        // if it throws here, the loader let something through.
        const wf::Bvh bvh = wf::build_scene_bvh(scene);
        wf::make_device_scene_data(scene, bvh);
    } catch (const wf::InputError&) {
    }
    return 0;
}
