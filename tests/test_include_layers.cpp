// test_include_layers.cpp — the layers of host/ (docs/how-it-works.md) hold:
// a file includes only its own layer and those below it, OpenCL's headers
// appear from device/ up, and in kernels/ ray traversal does not reach the
// BSDF. Read from the source tree, so a wrong include fails here, by name,
// rather than years later as a tangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#ifndef WF_SOURCE_DIR
#define WF_SOURCE_DIR "."
#endif

namespace {

namespace fs = std::filesystem;

// From the glTF file to the image: each layer may use those before it.
// session/ (a render from start to end) is what the front ends stand on:
// cluster/ (a render over MPI ranks), cli/ (the flags and the dispatch, which
// hands a render under mpirun to cluster/), app/ (main) and python/ (whose
// keywords are the command line's flags).
constexpr std::array<const char*, 14> kHostLayers = {"base",   "image",   "scene",      "gltf",   "bvh",
                                                     "device", "film",    "integrator", "render", "session",
                                                     "cluster", "cli",    "app",        "python"};
constexpr const char* kFirstOpenClLayer = "device";

int layer_rank(const std::string& name) {
    const auto it = std::find(kHostLayers.begin(), kHostLayers.end(), name);
    return it == kHostLayers.end() ? -1 : int(it - kHostLayers.begin());
}

// Each `#include "x/..."` and `#include <x/...>` of a file, as (quoted?, path).
std::vector<std::pair<bool, std::string>> includes_of(const fs::path& file) {
    static const std::regex include(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
    std::vector<std::pair<bool, std::string>> found;
    std::ifstream in(file);
    std::smatch m;
    for (std::string line; std::getline(in, line);)
        if (std::regex_search(line, m, include)) found.emplace_back(m[1] == "\"", m[2]);
    return found;
}

std::string first_folder(const std::string& path) { return path.substr(0, path.find('/')); }

TEST(IncludeLayers, HostIncludesRunDownward) {
    const fs::path host = fs::path(WF_SOURCE_DIR) / "host";
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(host)) {
        if (!entry.is_regular_file()) continue;
        const fs::path relative = fs::relative(entry.path(), host);
        const std::string layer = first_folder(relative.generic_string());
        const int rank = layer_rank(layer);
        ASSERT_GE(rank, 0) << "host/" << relative.generic_string() << ": host/" << layer
                           << " is not a layer of kHostLayers";
        ++files;
        for (const auto& [quoted, path] : includes_of(entry.path())) {
            if (!quoted && path.rfind("CL/", 0) == 0)
                EXPECT_GE(rank, layer_rank(kFirstOpenClLayer))
                    << "host/" << relative.generic_string() << " includes OpenCL below device/";
            if (!quoted || path.find('/') == std::string::npos) continue;
            const int used = layer_rank(first_folder(path));
            if (used >= 0)
                EXPECT_LE(used, rank) << "host/" << relative.generic_string() << " (" << layer
                                      << ") includes " << path << ", a layer above it";
        }
    }
    EXPECT_GT(files, 50);
}

// The alpha test needs textures, not materials: traversal must compile
// without the BSDF, so that intersect kernels stay small.
TEST(IncludeLayers, KernelTraversalDoesNotReachTheBsdf) {
    const fs::path kernels = fs::path(WF_SOURCE_DIR) / "kernels";
    std::vector<std::string> pending = {"geometry/bvh_traverse.h", "stages/intersect.h", "stages/intersect_shadow.h"};
    std::vector<std::string> seen;
    while (!pending.empty()) {
        const std::string file = pending.back();
        pending.pop_back();
        if (std::find(seen.begin(), seen.end(), file) != seen.end()) continue;
        seen.push_back(file);
        EXPECT_NE(first_folder(file), "bsdf") << "traversal reaches " << file;
        EXPECT_NE(file, "materials/surface_material.h") << "traversal reaches " << file;
        for (const auto& [quoted, path] : includes_of(kernels / file))
            if (quoted && fs::exists(kernels / path)) pending.push_back(path);
    }
    EXPECT_GT(seen.size(), 3u);
}

} // namespace
