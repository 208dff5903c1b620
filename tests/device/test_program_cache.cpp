// test_program_cache.cpp — compiled programs kept on disk (host/device/program_cache.h)
// are used again only for exactly the program they were built from: the same
// expanded source, build options (the scene's features among them) and
// device. A stale, colliding or torn entry is never run.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "device/kernel_program.h"
#include "device/kernel_sources.h"
#include "device/program_cache.h"
#include "render/renderer.h"
#include "support/test_support.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

class ProgramCacheTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("wavefront_cache_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    size_t entries() const {
        size_t n = 0;
        for (const auto& e : fs::directory_iterator(dir_)) n += e.path().extension() == ".clbin";
        return n;
    }
    fs::path dir_;
};

TEST_F(ProgramCacheTest, TheSecondBuildComesFromTheCacheAndRendersTheSameBits) {
    const ProgramCache cache(dir_);
    const OpenClDevice& device = test::cpu_device();
    const KernelProgram cold = build_kernel_program(device, "wavefront.cl", "-DWF_HAS_ENVIRONMENT=0", &cache);
    EXPECT_FALSE(cold.from_cache);
    EXPECT_EQ(entries(), 1u);
    const KernelProgram warm = build_kernel_program(device, "wavefront.cl", "-DWF_HAS_ENVIRONMENT=0", &cache);
    EXPECT_TRUE(warm.from_cache);
    test::report_measured("wavefront.cl on " + device.info.name + ": built in " + std::to_string(cold.build_seconds) +
                          " s, loaded from the cache in " + std::to_string(warm.build_seconds) + " s");

    // A render through the cache gives the bytes of one without it.
    const Scene scene = test::furnace_box(0.5f, 1.0f);
    RenderSettings settings;
    settings.spp = 2;
    const SceneCamera camera = test::camera_looking({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1.0f);
    const RenderOutput uncached = render_scene(device, scene, camera, ImageSize{16, 16}, settings);
    settings.cache_dir = dir_.string();
    const RenderOutput first = render_scene(device, scene, camera, ImageSize{16, 16}, settings);
    const RenderOutput second = render_scene(device, scene, camera, ImageSize{16, 16}, settings);
    EXPECT_FALSE(first.summary.kernels_from_cache);
    EXPECT_TRUE(second.summary.kernels_from_cache);
    EXPECT_EQ(second.film.mean.rgb, uncached.film.mean.rgb);
}

TEST_F(ProgramCacheTest, AnyChangeInSourceOptionsOrDeviceMakesANewKey) {
    const DeviceInfo& device = test::cpu_device().info;
    const std::string source = expand_kernel_source("wavefront.cl");
    const std::string key = program_cache_key(device, "-DWF_HAS_TEXTURES=0", source);
    EXPECT_NE(key, program_cache_key(device, "-DWF_HAS_TEXTURES=1", source));
    // An edit in an included header shows in the expanded source.
    EXPECT_NE(key, program_cache_key(device, "-DWF_HAS_TEXTURES=0", source + " "));
    DeviceInfo updated = device;
    updated.driver += "+1";
    EXPECT_NE(key, program_cache_key(updated, "-DWF_HAS_TEXTURES=0", source));
    // A feature set builds its own entry.
    const ProgramCache cache(dir_);
    const OpenClDevice& d = test::cpu_device();
    build_kernel_program(d, "wavefront.cl", "-DWF_HAS_TEXTURES=0", &cache);
    EXPECT_FALSE(build_kernel_program(d, "wavefront.cl", "-DWF_HAS_TEXTURES=1", &cache).from_cache);
    EXPECT_EQ(entries(), 2u);
}

TEST_F(ProgramCacheTest, StaleOrTornEntriesAreNeverUsed) {
    const ProgramCache cache(dir_);
    cache.store("key one", {1, 2, 3, 4});
    ASSERT_TRUE(cache.load("key one"));
    EXPECT_EQ(*cache.load("key one"), (std::vector<unsigned char>{1, 2, 3, 4}));
    // The entry of another key, under this key's file name (a hash collision,
    // or a file copied from elsewhere): the stored key differs, so no binary.
    const fs::path one = fs::directory_iterator(dir_)->path();
    cache.store("key two", {5, 6});
    fs::path two;
    for (const auto& e : fs::directory_iterator(dir_))
        if (e.path() != one) two = e.path();
    fs::rename(two, one);
    EXPECT_FALSE(cache.load("key one"));
    // A torn entry (cut short) is not used either, and a build replaces it.
    const OpenClDevice& device = test::cpu_device();
    build_kernel_program(device, "wavefront.cl", "", &cache);
    for (const auto& e : fs::directory_iterator(dir_)) fs::resize_file(e.path(), fs::file_size(e.path()) / 2);
    const KernelProgram rebuilt = build_kernel_program(device, "wavefront.cl", "", &cache);
    EXPECT_FALSE(rebuilt.from_cache);
    EXPECT_TRUE(build_kernel_program(device, "wavefront.cl", "", &cache).from_cache);
    EXPECT_GT(cache.clear(), 0u);
    EXPECT_EQ(entries(), 0u);
}

TEST_F(ProgramCacheTest, WarmAndClearFromTheCommandLine) {
    fs::create_directories(dir_);
    const std::string cornell = WF_SOURCE_DIR "/scenes/cornell-box.gltf";
    const test::ProcessResult warm = test::run_wavefront("cache warm '" + cornell + "' --cache-dir '" + dir_.string() + "'", dir_.string());
    ASSERT_EQ(warm.exit_code, 0) << warm.err;
    EXPECT_NE(warm.out.find("emissive triangles, specular: compiled"), std::string::npos) << warm.out;
    const test::ProcessResult render = test::run_wavefront("render '" + cornell + "' --width 16 --spp 1 --cache-dir '" +
                                                               dir_.string() + "' -o '" + (dir_ / "x.png").string() + "'",
                                                           dir_.string());
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_NE(render.out.find("(from cache)"), std::string::npos) << render.out;
    const test::ProcessResult clear = test::run_wavefront("cache clear --cache-dir '" + dir_.string() + "'", dir_.string());
    ASSERT_EQ(clear.exit_code, 0) << clear.err;
    EXPECT_NE(clear.out.find("removed 1 "), std::string::npos) << clear.out;
    for (const std::string& bad : {"cache", "cache warm", "cache burn", "cache clear extra", "cache warm --bogus x"}) {
        const test::ProcessResult r = test::run_wavefront(bad, dir_.string());
        EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.err;
    }
}

} // namespace
} // namespace wf
