// test_multi_device_cli.cpp — `--device all` and `--device 0,1` over two real
// PoCL devices (POCL_DEVICES="pthread pthread", one thread each) give the
// bytes of one device's render, the report gives each device's share, and a
// list that names a device twice or none is refused by name.
#include <cstring>
#include <filesystem>

#include <unistd.h>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "support/scratch_folder.h"
#include "support/test_support.h"

namespace wf {
namespace {

namespace fs = std::filesystem;
const std::string kCornell = WF_SOURCE_DIR "/scenes/cornell-box.gltf";
const std::string kTwoDevices = "POCL_DEVICES='pthread pthread' POCL_MAX_PTHREAD_COUNT=1";

class MultiDeviceCli : public test::ScratchFolder {
protected:
    test::ProcessResult render(const std::string& device, const std::string& output) const {
        return test::run_wavefront("render " + kCornell + " --width 64 --spp 6 --seed 4 --pool-size 700 --device " +
                                       device + " --cache-dir " + path("cache") + " -o " + output,
                                   dir_.string(), kTwoDevices);
    }
};

bool same_pixels(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

TEST_F(MultiDeviceCli, TwoPoclDevicesGiveTheBytesOfOne) {
    const test::ProcessResult one = render("0", path("one.exr"));
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const test::ProcessResult all = render("all", path("all.exr"));
    ASSERT_EQ(all.exit_code, 0) << all.err;
    EXPECT_NE(all.out.find("device     2 devices"), std::string::npos) << all.out;
    EXPECT_NE(all.out.find("  [0]      "), std::string::npos) << all.out;
    EXPECT_NE(all.out.find("  [1]      "), std::string::npos) << all.out;
    EXPECT_NE(all.out.find("% of the samples in "), std::string::npos) << all.out;
    EXPECT_TRUE(same_pixels(read_image(path("one.exr")), read_image(path("all.exr"))));
    const test::ProcessResult list = render("1,0", path("list.exr"));
    ASSERT_EQ(list.exit_code, 0) << list.err;
    EXPECT_TRUE(same_pixels(read_image(path("one.exr")), read_image(path("list.exr"))));
}

TEST_F(MultiDeviceCli, ABadListIsRefusedByName) {
    test::ProcessResult r = render("0,0", path("twice.exr"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--device 0,0: device 0 is named twice"), std::string::npos) << r.err;
    r = render("0,7", path("none.exr"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--device 7: no such device (there are 2"), std::string::npos) << r.err;
    r = render("0,", path("empty.exr"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--device 0,: an empty entry in the list"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("twice.exr")) || fs::exists(path("none.exr")) || fs::exists(path("empty.exr")));
}

// Adaptive sampling continues a list of pixels on one device; units of work
// over several are runs of pixels. Refused before any round, by name.
TEST_F(MultiDeviceCli, AdaptiveSamplingOverSeveralDevicesIsRefused) {
    const test::ProcessResult r =
        test::run_wavefront("render " + kCornell + " --width 32 --adaptive --target-error 0.01 --device all -o " +
                                path("adaptive.exr"),
                            dir_.string(), kTwoDevices);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--adaptive samples the image on one device"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("adaptive.exr")));
}

} // namespace
} // namespace wf
