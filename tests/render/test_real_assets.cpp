// test_real_assets.cpp — every glTF asset in ../shared/scenes-real/ (made by
// others, with features this renderer may not have) renders at low resolution
// through the `wavefront` executable: exit code 0, no non-finite sample, and
// every unsupported feature the inventory lists reported as a warning rather
// than dropped in silence.
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

const fs::path kAssets = fs::path(WF_SOURCE_DIR) / ".." / "shared" / "scenes-real";

// The scene file of each asset folder (the one .gltf or .glb in it).
std::vector<fs::path> asset_files() {
    std::vector<fs::path> files;
    if (!fs::is_directory(kAssets)) return files;
    for (const fs::directory_entry& dir : fs::directory_iterator(kAssets)) {
        if (!dir.is_directory()) continue;
        for (const fs::directory_entry& f : fs::directory_iterator(dir.path()))
            if (f.path().extension() == ".gltf" || f.path().extension() == ".glb") files.push_back(f.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// What the report must warn about for the assets whose features are not
// supported (from ../shared/scenes-real/INVENTORY.md).
const std::map<std::string, std::vector<std::string>> kExpectedWarnings = {
    {"Fox.gltf", {"skin"}},
    {"Box.gltf", {"no light"}},
    {"DamagedHelmet.glb", {"occlusion maps"}},
};

TEST(RealAssets, EveryAssetRendersWithoutNonFiniteSamples) {
    const std::vector<fs::path> files = asset_files();
    ASSERT_GE(files.size(), 19u) << "expected the assets of " << kAssets;
    const fs::path scratch = fs::temp_directory_path() / ("wavefront_assets_" + std::to_string(::getpid()));
    fs::create_directories(scratch);
    for (const fs::path& file : files) {
        const test::ProcessResult r = test::run_wavefront(
            "render '" + file.string() + "' --width 24 --height 24 --spp 2 -o '" + (scratch / "out.exr").string() + "'",
            scratch.string());
        EXPECT_EQ(r.exit_code, 0) << file << "\n" << r.err;
        EXPECT_NE(r.out.find("non-finite samples 0\n"), std::string::npos) << file << "\n" << r.out;
        const auto expected = kExpectedWarnings.find(file.filename().string());
        if (expected != kExpectedWarnings.end())
            for (const std::string& feature : expected->second)
                EXPECT_NE(r.err.find(feature), std::string::npos) << file << " should warn of " << feature << "\n" << r.err;
    }
    fs::remove_all(scratch);
}

} // namespace
} // namespace wf
