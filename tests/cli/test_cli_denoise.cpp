// test_cli_denoise.cpp — `wavefront render --denoise` as a user meets it: the
// denoised image written, the noisy one kept as an EXR layer with the bytes
// of a render without --denoise, and, without Open Image Denoise, one line
// saying how to install it, exit status 2 and no file touched. The tests that
// need the library are skipped where it is absent (denoiser_present.h).
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "support/denoiser_present.h"
#include "support/scratch_folder.h"
#include "support/test_support.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

const std::string kCornell = WF_SOURCE_DIR "/scenes/cornell-box.gltf";
const std::string kSmall = "render " + kCornell + " --width 32 --spp 4 --seed 7 --quiet ";

class CliDenoise : public test::ScratchFolder {
protected:
    test::ProcessResult run(const std::string& args, const std::string& env = "") const {
        return test::run_wavefront(args, dir_.string(), env);
    }
};

// The channels `names` of an image read by name, pixel after pixel.
std::vector<float> channels(const ChannelImage& image, const std::vector<std::string>& names) {
    std::vector<size_t> at;
    for (const std::string& n : names) {
        const auto found = std::find(image.channel_names.begin(), image.channel_names.end(), n);
        EXPECT_NE(found, image.channel_names.end()) << n;
        if (found == image.channel_names.end()) return {};
        at.push_back(size_t(found - image.channel_names.begin()));
    }
    std::vector<float> values;
    const size_t stride = image.channel_names.size();
    for (size_t p = 0; p < size_t{image.width} * image.height; ++p)
        for (size_t c : at) values.push_back(image.pixels[p * stride + c]);
    return values;
}

bool same_bytes(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// A library that cannot be opened: one line naming where it looked and both
// ways to install it, exit 2, and neither a new file nor an old one touched.
TEST_F(CliDenoise, WithoutTheLibraryOneLineSaysHowToInstallItAndNothingIsWritten) {
    std::ofstream(path("old.exr")) << "an older image";
    for (const std::string& out : {"old.exr", "new.exr", "new.png"}) {
        const test::ProcessResult r = run(kSmall + "--denoise -o " + path(out), "WF_OIDN_LIBRARY=/nonexistent/libOpenImageDenoise.so.2");
        EXPECT_EQ(r.exit_code, 2) << out << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        for (const char* names : {"Open Image Denoise not found", "/nonexistent/libOpenImageDenoise.so.2",
                                  "scripts/setup.sh", "WF_OIDN_LIBRARY", "pip install pyoidn"})
            EXPECT_NE(r.err.find(names), std::string::npos) << "'" << r.err << "' should name '" << names << "'";
    }
    EXPECT_EQ(test::read_file(path("old.exr")), "an older image");
    EXPECT_FALSE(fs::exists(path("new.exr")));
    EXPECT_FALSE(fs::exists(path("new.png")));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1 + 2) // old.exr, out, err
        << "a file beside old.exr";
}

// The EXR holds the denoised image as RGB and the noisy one as noisy.R/G/B,
// whose bytes are those of the same render without --denoise; the albedo and
// normal it was guided by are layers too, and the metadata names the denoiser.
TEST_F(CliDenoise, TheExrKeepsTheNoisyImageBitForBit) {
    WF_SKIP_WITHOUT_OIDN();
    const test::ProcessResult denoised = run(kSmall + "--denoise -o " + path("denoised.exr"));
    ASSERT_EQ(denoised.exit_code, 0) << denoised.err;
    ASSERT_EQ(run(kSmall + "-o " + path("plain.exr")).exit_code, 0);
    const ChannelImage d = read_channels(path("denoised.exr"));
    const ChannelImage plain = read_channels(path("plain.exr"));
    const std::vector<float> noisy = channels(d, {"noisy.R", "noisy.G", "noisy.B"});
    const std::vector<float> rgb = channels(plain, {"R", "G", "B"});
    EXPECT_TRUE(same_bytes(noisy, rgb)) << "the noisy layer is not the render without --denoise";
    EXPECT_FALSE(same_bytes(channels(d, {"R", "G", "B"}), rgb)) << "the image was not denoised";
    for (const char* name : {"albedo.R", "normal.X"})
        EXPECT_NE(std::find(d.channel_names.begin(), d.channel_names.end(), name), d.channel_names.end()) << name;
    const auto option = [](const ChannelImage& image, const std::string& name) {
        for (const auto& [key, value] : image.options)
            if (key == name) return value;
        return std::string("absent");
    };
    EXPECT_NE(option(d, "denoise").find("Open Image Denoise"), std::string::npos) << option(d, "denoise");
    EXPECT_EQ(option(plain, "denoise"), "absent");
}

// An 8-bit output holds the denoised image alone; an image that can be
// neither checkpointed nor resumed says so.
TEST_F(CliDenoise, APngHoldsTheDenoisedImageAndPartialRendersAreRefused) {
    WF_SKIP_WITHOUT_OIDN();
    const test::ProcessResult png = run(kSmall + "--denoise -o " + path("denoised.png"));
    ASSERT_EQ(png.exit_code, 0) << png.err;
    const Image image = read_image(path("denoised.png"));
    EXPECT_EQ(image.width, 32u);
    EXPECT_GT(test::channel_stats(image, 0).mean, 0.05);
    const test::ProcessResult checkpointed = run(kSmall + "--denoise --checkpoint-every 10 -o " + path("c.exr"));
    EXPECT_EQ(checkpointed.exit_code, 2);
    EXPECT_NE(checkpointed.err.find("--denoise cannot be checkpointed or resumed"), std::string::npos)
        << checkpointed.err;
}

} // namespace
} // namespace wf
