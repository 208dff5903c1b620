// test_cli.cpp — the `wavefront` executable as a user meets it: exit codes,
// one-line errors that name the thing at fault, and the files it writes.

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "image/image_io.h"
#include "support/scratch_folder.h"
#include "support/test_support.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

class Cli : public test::ScratchFolder {
protected:
    test::ProcessResult run(const std::string& args) const { return test::run_wavefront(args, dir_.string()); }

    // A bad invocation: exit code 2 and exactly one line on stderr containing `names`.
    void expect_rejected(const std::string& args, const std::string& names) const {
        const test::ProcessResult r = run(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_NE(r.err.find(names), std::string::npos) << args << ": '" << r.err << "' should name '" << names << "'";
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": '" << r.err << "'";
    }

    void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
};

const std::string kCornell = WF_SOURCE_DIR "/scenes/cornell-box.gltf";

// Every command takes --help; every flag of `render --help` says its default
// and shows its check (a range or the choices); --version names the commit,
// the build type and what it runs on.
TEST_F(Cli, HelpDocumentsEveryFlagWithItsDefault) {
    const test::ProcessResult top = run("--help");
    EXPECT_EQ(top.exit_code, 0);
    for (const char* command : {"render", "devices", "cache", "--version"})
        EXPECT_NE(top.out.find(command), std::string::npos) << command;
    for (const char* command : {"devices --help", "cache --help", "cache warm --help", "cache clear --help"}) {
        const test::ProcessResult help = run(command);
        EXPECT_EQ(help.exit_code, 0) << command;
        EXPECT_NE(help.out.find("Usage: wavefront " + std::string(command).substr(0, std::string(command).find(" --"))),
                  std::string::npos)
            << help.out;
    }
    const test::ProcessResult help = run("render --help");
    EXPECT_EQ(help.exit_code, 0);
    // A flag's entry starts with "  -" and its help may wrap onto the next line.
    std::vector<std::string> entries;
    std::istringstream lines(help.out);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("  -", 0) == 0) entries.push_back(line);
        else if (!entries.empty() && line.rfind("      ", 0) == 0) entries.back() += line;
    }
    for (const std::string& entry : entries)
        if (entry.find("--help") == std::string::npos)
            EXPECT_NE(entry.find("(default: "), std::string::npos) << entry;
    EXPECT_GE(entries.size(), 34u);
    for (const char* check : {"--spp UINT:in 1 to 16777216", "--sampler TEXT:{independent,sobol}"})
        EXPECT_NE(help.out.find(check), std::string::npos) << check;

    const test::ProcessResult version = run("--version");
    EXPECT_EQ(version.exit_code, 0);
    for (const char* part : {"wavefront " WF_VERSION "\n", "commit ", "build ", "OpenCL ", "Portable Computing Language: OpenCL",
                             "PoCL ", "OpenImageIO 2."})
        EXPECT_NE(version.out.find(part), std::string::npos) << part << " not in " << version.out;
}

// --config FILE holds flags in TOML, at the top or under [render]; flags on
// the command line win; a key that is no render flag, or a bad value, is named.
TEST_F(Cli, AConfigFileHoldsFlagsAndTheCommandLineWins) {
    write("render.toml", "spp = 3\n[ render ]\nwidth = 24\nseed = 7\n"); // TOML allows the spaces
    const test::ProcessResult r = run("render " + kCornell + " --config " + path("render.toml") + " --spp=5 -o " +
                                      path("c.exr"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("24 x 24, 5 spp"), std::string::npos) << r.out;
    auto in = OIIO::ImageInput::open(path("c.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_string_attribute("wavefront:option:seed"), "7");

    write("quiet.toml", "quiet = true\nspp = 2\nwidth = 16\n");
    const test::ProcessResult quiet = run("render " + kCornell + " --config=" + path("quiet.toml") + " -o " + path("q.png"));
    EXPECT_EQ(quiet.exit_code, 0);
    EXPECT_EQ(quiet.out + quiet.err, ""); // --quiet: errors only

    write("unknown.toml", "frobnicate = 1\n");
    expect_rejected("render " + kCornell + " --config " + path("unknown.toml"), "unknown.toml:1: 'frobnicate' is not a render flag");
    write("bad.toml", "spp = 0\n");
    expect_rejected("render " + kCornell + " --config " + path("bad.toml"), "--spp: 0 is not in");
    expect_rejected("render " + kCornell + " --config " + path("missing.toml"), "missing.toml");
}

// A config file that is not one, or not one a person wrote, is refused in one
// line of at most 200 characters that names the file and the line at fault.
TEST_F(Cli, ConfigErrorsAreOneShortLineNamingTheLine) {
    const auto expect_line = [&](const std::string& name, const std::string& text, const std::string& names) {
        write(name, text);
        const test::ProcessResult r = run("render " + kCornell + " --config " + path(name) + " -o " + path("c.png"));
        EXPECT_EQ(r.exit_code, 2) << name << ": " << r.err;
        EXPECT_NE(r.err.find(path(name) + names), std::string::npos) << name << ": '" << r.err << "'";
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_LE(r.err.size(), std::string("error: \n").size() + 200) << r.err;
    };
    expect_line("png.toml", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), ":2: not a text file");
    expect_line("words.toml", "width = 16\nthis is not toml\n", ":2: 'this is not toml' is not 'name = value'");
    expect_line("deep.toml", "spp = 2\nwidth = " + std::string(5000, '[') + std::string(5000, ']') + "\n",
                ":2: 'width' takes one value, not an array");
    expect_line("long.toml", "spp = " + std::string(20000, '9') + "\n", ":1: render: --spp: ");
    expect_line("open.toml", "output = \"x.png\n", ":1: a quote (\") is not closed");
    expect_line("empty.toml", "\n\nspp =\n", ":3: 'spp' has no value");
    expect_line("twice.toml", "spp = 2\n[render]\nspp = 3\n", ":3: 'render.spp' gives --spp again (first on line 1)");
    expect_line("value.toml", "width = 16\n\n# samples\nspp = 0\n", ":4: render: --spp: 0 is not in");
    EXPECT_FALSE(fs::exists(path("c.png")));
}

// Only regular files are read: a FIFO, a device or a folder where a scene,
// one of its buffers, a config, a reference, an environment map or a partial
// render should be is refused at once, without opening it (opening a FIFO
// waits for a writer forever).
TEST_F(Cli, WhatIsNotARegularFileIsRefusedAtOnce) {
    ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
    fs::create_directories(dir_ / "folder.gltf");
    const auto expect_refused = [&](const std::string& args, const std::string& names) {
        const test::ProcessResult r = test::run_wavefront(args + " -o " + path("out.exr"), dir_.string(), "", 60);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err; // 124: it waited
        EXPECT_NE(r.err.find(names), std::string::npos) << args << ": '" << r.err << "' should name '" << names << "'";
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": '" << r.err << "'";
    };
    const std::string small = "render " + kCornell + " --width 16 --spp 1 ";
    expect_refused("render " + path("fifo"), "fifo: a FIFO, not a regular file");
    expect_refused("render " + path("folder.gltf"), "folder.gltf: a directory, not a regular file");
    expect_refused("render /dev/zero", "/dev/zero: a device, not a regular file");
    expect_refused(small + "--config " + path("fifo"), "fifo: config file: a FIFO");
    expect_refused(small + "--reference " + path("fifo"), "fifo: image: a FIFO");
    expect_refused(small + "--env " + path("fifo"), "fifo: environment map: a FIFO");
    expect_refused(small + "--resume " + path("fifo"), "fifo: image: a FIFO");

    fs::create_directories(dir_ / "scene");
    ASSERT_EQ(::mkfifo(path("scene/data.bin").c_str(), 0600), 0);
    write("scene/pipe.gltf",
          R"({"asset":{"version":"2.0"},"buffers":[{"uri":"data.bin","byteLength":36}],)"
          R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
          R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}],)"
          R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})");
    expect_refused("render " + path("scene/pipe.gltf"), "data.bin, a FIFO, not a regular file");
    EXPECT_FALSE(fs::exists(path("out.exr")));
}

// A reader that goes away before the render ends (`| head -1`) costs neither
// the image nor the exit code, on stdout or on stderr.
TEST_F(Cli, AClosedPipeCostsNothing) {
    const std::string render = "'" WF_BINARY "' render " + kCornell + " --width 16 --spp 1 -o " + path("x.png");
    for (const std::string redirect : {"", " 2>&1 >/dev/null"}) {
        fs::remove(path("x.png"));
        // `true` exits at once: every write to the pipe finds it closed.
        const std::string command = "{ " + render + redirect + "; echo $? > " + path("status") + "; } | true";
        ASSERT_EQ(std::system(("sh -c \"" + command + "\"").c_str()), 0) << command;
        EXPECT_EQ(test::read_file(path("status")), "0\n") << command; // 141: killed by SIGPIPE
        EXPECT_TRUE(fs::exists(path("x.png"))) << command;
    }
}

// PoCL offers no device when it cannot make its kernel cache: the error says
// so, instead of blaming the driver.
TEST_F(Cli, AnUnwritableHomeIsNamedNotABrokenDriver) {
    const std::string err = path("stderr.txt");
    const std::string command = std::string("env -u XDG_CACHE_HOME -u POCL_CACHE_DIR HOME=/dev/null '") + WF_BINARY +
                                "' devices 2> '" + err + "' > /dev/null";
    const int status = std::system(command.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1);
    const std::string text = test::read_file(err);
    EXPECT_NE(text.find("PoCL cannot create its kernel cache in /dev/null/.cache/pocl (from HOME)"), std::string::npos)
        << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
}

TEST_F(Cli, BadFlagsAreRejectedByName) {
    expect_rejected("render " + kCornell + " --spp 0", "render: --spp: 0 is not in 1 to 16777216");
    expect_rejected("render " + kCornell + " --spp abc", "--spp: 'abc' is not a whole number");
    expect_rejected("render " + kCornell + " --spp=abc", "--spp: 'abc'"); // --opt=value reads the same
    expect_rejected("render " + kCornell + " --width -5", "--width: -5 is not in 1 to 32768");
    expect_rejected("render " + kCornell + " --width 100000 --height 100000", "--width: 100000");
    expect_rejected("render " + kCornell + " --roulette-cap 0", "--roulette-cap: 0 is not in (0, 1]");
    expect_rejected("render " + kCornell + " --roulette-cap 1.5", "--roulette-cap: 1.5 is not in (0, 1]");
    expect_rejected("render " + kCornell + " --lane-width 4", "--lane-width: 4");
    expect_rejected("render " + kCornell + " --trace-width 3", "--trace-width: 3");
    expect_rejected("render " + kCornell + " --shade-kernels 3", "--shade-kernels: 3");
    expect_rejected("render " + kCornell + " --look-at 1,2,3", "--look-at 1,2,3: expected six or nine numbers, not 3");
    expect_rejected("render " + kCornell + " --look-at 1,2,x,4,5,6", "--look-at 1,2,x,4,5,6: expected six or nine");
    expect_rejected("render " + kCornell + " --look-at 1,2,3,1,2,3", "--look-at: the eye is the target");
    expect_rejected("render " + kCornell + " --look-at 0,0,0,0,1,0", "--look-at: the up direction lies along");
    expect_rejected("render " + kCornell + " --look-at 0,0,0,0,0,1 --camera 0", "--camera excludes --look-at");
    expect_rejected("render " + kCornell + " --fov 180", "--fov: 180 is not in (0, 180)");
    expect_rejected("render " + kCornell + " --frobnicate", "frobnicate");
    expect_rejected("render", "no scene file");
    expect_rejected("paint " + kCornell, "unknown command 'paint'");
    expect_rejected("render " + kCornell + " --device 99 -o " + path("x.png"), "--device 99");
    // 2^30 pixels need 36 GiB of film: refused, saying so, before any allocation.
    expect_rejected("render " + kCornell + " --width 32768 --height 32768 -o " + path("x.png"), "device memory");
    EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(Cli, BadScenesAreRejectedByName) {
    expect_rejected("render " + path("missing.gltf"), "missing.gltf");
    write("broken.gltf", "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ ");
    expect_rejected("render " + path("broken.gltf"), "broken.gltf");
    // One triangle whose second corner is NaN: the buffer holds 3 floats per corner.
    const std::string nan_triangle = "AAAAAAAAAAAAAAAAAADAfwAAAAAAAAAAAAAAAAAAgD8AAAAA"; // base64 of 9 floats
    write("nan.gltf", std::string(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
      "meshes":[{"name":"spiky","primitives":[{"attributes":{"POSITION":0}}]}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
      "bufferViews":[{"buffer":0,"byteLength":36}],
      "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)") + nan_triangle + R"("}]})");
    expect_rejected("render " + path("nan.gltf"), "spiky");
}

// --exposure brightens an 8-bit output by 2^EV before the sRGB curve and is
// refused for a float output, which keeps radiance; --half stores an EXR's
// channels as halves, the float render rounded to the nearest half.
TEST_F(Cli, ExposureScalesEightBitOutputsAndHalfStoresHalves) {
    const std::string base = "render " + kCornell + " --width 32 --spp 4 --seed 2 --quiet -o ";
    ASSERT_EQ(run(base + path("plain.png")).exit_code, 0);
    ASSERT_EQ(run(base + path("bright.png") + " --exposure 1").exit_code, 0);
    ASSERT_EQ(run(base + path("dark.png") + " --exposure=-2").exit_code, 0);
    ASSERT_EQ(run(base + path("float.exr")).exit_code, 0);
    ASSERT_EQ(run(base + path("half.exr") + " --half").exit_code, 0);
    const Image linear = read_image(path("float.exr")), plain = read_image(path("plain.png"));
    const Image bright = read_image(path("bright.png")), dark = read_image(path("dark.png"));
    // One 8-bit step of the sRGB curve, in linear terms, bounds the difference.
    for (size_t i = 0; i < linear.rgb.size(); ++i) {
        const float v = linear.rgb[i], step = 0.01f + 0.02f * v;
        EXPECT_NEAR(plain.rgb[i], std::min(v, 1.0f), step) << i;
        EXPECT_NEAR(bright.rgb[i], std::min(2.0f * v, 1.0f), 2.0f * step) << i;
        EXPECT_NEAR(dark.rgb[i], std::min(0.25f * v, 1.0f), step) << i;
    }
    auto in = OIIO::ImageInput::open(path("half.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::HALF);
    in->close();
    const Image half = read_image(path("half.exr"));
    for (size_t i = 0; i < linear.rgb.size(); ++i)
        EXPECT_NEAR(half.rgb[i], linear.rgb[i], 1e-3f * linear.rgb[i] + 1e-7f) << i; // half: 11 significant bits
    expect_rejected(base + path("e.exr") + " --exposure 1", "--exposure 1: " + path("e.exr") + " keeps linear radiance");
    expect_rejected(base + path("h.png") + " --half", "--half: " + path("h.png") + " is not a float format");
    expect_rejected(base + path("x.png") + " --exposure 100", "--exposure: 100 is not in -64 to 64");
}

// --aov takes a list: the first hit's layers and the bounce layers, named in
// the EXR as a compositor expects (albedo.R, normal.X, depth.Z, bounce0.R).
TEST_F(Cli, AovsAreLayersOfTheExr) {
    const std::string base = "render " + kCornell + " --width 24 --spp 2 --quiet ";
    ASSERT_EQ(run(base + "--aov albedo,normal,depth,bounces -o " + path("aov.exr")).exit_code, 0);
    const ChannelImage image = read_channels(path("aov.exr"));
    for (const char* name : {"R", "albedo.R", "albedo.B", "normal.X", "normal.Z", "depth.Z", "bounce0.R",
                             "bounce7plus.B"})
        EXPECT_NE(std::find(image.channel_names.begin(), image.channel_names.end(), name), image.channel_names.end())
            << name;
    EXPECT_EQ(image.channel_names.size(), 3u + 3u + 3u + 1u + 8u * 3u);
    const auto aov = std::find_if(image.options.begin(), image.options.end(), [](auto& o) { return o.first == "aov"; });
    ASSERT_NE(aov, image.options.end());
    EXPECT_EQ(aov->second, "albedo,normal,depth,bounces");
    expect_rejected(base + "--aov albedo -o " + path("a.png"), "--aov layers need a float format");
    expect_rejected(base + "--aov albedo,shadows -o " + path("a.exr"), "--aov");
}

// --adaptive: each pixel's count as the layer samples.Y, and the report's
// fewest, most and mean; without a target there is nothing to stop on.
TEST_F(Cli, AdaptiveSamplingKeepsEachPixelsCount) {
    const std::string base = "render " + kCornell + " --width 24 --spp 64 --adaptive ";
    const test::ProcessResult r = run(base + "--target-error 0.03 --aov samples -o " + path("adaptive.exr"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const ChannelImage image = read_channels(path("adaptive.exr"));
    const auto channel = std::find(image.channel_names.begin(), image.channel_names.end(), "samples.Y");
    ASSERT_NE(channel, image.channel_names.end());
    const size_t first = channel - image.channel_names.begin(), stride = image.channel_names.size();
    float fewest = 1e9f, most = 0.0f;
    for (size_t p = first; p < image.pixels.size(); p += stride) {
        fewest = std::min(fewest, image.pixels[p]);
        most = std::max(most, image.pixels[p]);
    }
    EXPECT_EQ(fewest, 16.0f);
    EXPECT_EQ(most, 64.0f);
    EXPECT_NE(r.out.find(", 16 to 64 spp, "), std::string::npos) << r.out;
    expect_rejected(base + "-o " + path("a.exr"), "--adaptive shares the samples out toward --target-error");
    EXPECT_FALSE(fs::exists(path("a.exr")));
}

TEST_F(Cli, RendersPngAndExrWithMetadata) {
    const test::ProcessResult png = run("render " + kCornell + " --width 32 --height 32 --spp 2 -o " + path("cornell.png"));
    ASSERT_EQ(png.exit_code, 0) << png.err;
    EXPECT_NE(png.out.find("non-finite samples 0"), std::string::npos) << png.out;
    const test::ProcessResult exr = run("render " + kCornell + " --width 32 --spp 2 --seed 5 -o " + path("cornell.exr"));
    ASSERT_EQ(exr.exit_code, 0) << exr.err;

    auto in = OIIO::ImageInput::open(path("cornell.png"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(in->spec().width, 32);
    // 8-bit writers keep strings alone: the numbers are written as text.
    EXPECT_EQ(in->spec().get_string_attribute("wavefront:samplesPerPixel"), "2");
    EXPECT_EQ(in->spec().get_string_attribute("wavefront:seed"), "0");
    EXPECT_EQ(in->spec().get_string_attribute("wavefront:interrupted"), "0");
    EXPECT_GT(std::stod(in->spec().get_string_attribute("wavefront:renderTimeSeconds", "0")), 0.0);
    EXPECT_EQ(in->spec().get_string_attribute("wavefront:option:size"), "32x32");
    in = OIIO::ImageInput::open(path("cornell.exr"));
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(spec.height, 32); // the camera's aspect is 1
    EXPECT_EQ(spec.get_int_attribute("wavefront:samplesPerPixel"), 2);
    EXPECT_EQ(spec.get_int_attribute("wavefront:seed"), 5);
    EXPECT_GT(spec.get_float_attribute("wavefront:renderTimeSeconds"), 0.0f);
    EXPECT_FALSE(spec.get_string_attribute("wavefront:device").empty());
    EXPECT_EQ(spec.get_string_attribute("wavefront:option:seed"), "5");
    EXPECT_EQ(spec.get_string_attribute("wavefront:option:size"), "32x32");
    EXPECT_EQ(spec.get_string_attribute("wavefront:option:camera"), "first");
    EXPECT_EQ(spec.get_string_attribute("wavefront:option:version"), WF_VERSION);
    EXPECT_EQ(spec.get_int_attribute("wavefront:interrupted", -1), 0);
}

// Files from anywhere, written to anywhere: odd names work, and every place
// that cannot work is named in one line, exit 2, before any rendering and
// with no output file left behind.
// A reference in an 8-bit format holds sRGB-encoded values: it is decoded to
// linear before the comparison, so a render against its own PNG shows only
// the 8-bit rounding, where comparing encoded values as if linear would not.
TEST_F(Cli, An8BitReferenceIsComparedAsItIsStored) {
    const std::string small = "render " + kCornell + " --width 32 --spp 4 --seed 3 ";
    ASSERT_EQ(run(small + "-o " + path("ref.png")).exit_code, 0);
    ASSERT_EQ(run(small + "-o " + path("ref.exr")).exit_code, 0);
    const Image linear = read_image(path("ref.exr")), decoded = read_image(path("ref.png"));
    ASSERT_EQ(linear.rgb.size(), decoded.rgb.size());
    for (size_t i = 0; i < linear.rgb.size(); ++i) {
        const float expected = std::min(linear.rgb[i], 1.0f);
        ASSERT_NEAR(decoded.rgb[i], expected, 0.5f / 255.0f * 3.0f + 0.01f * expected) << i;
    }
    const test::ProcessResult r = run(small + "--reference " + path("ref.png") + " -o " + path("again.exr"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("relmse"), std::string::npos);
    // The same render against its own PNG has no error: it is compared as the
    // PNG stores it (clipped, quantised), which is said once. Compared
    // unclipped, the lamp alone made relMSE 8.3 at 512 x 512.
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("ref.png holds 256 levels a channel"), std::string::npos) << r.err;
    std::istringstream table(r.out);
    int rows = 0;
    for (std::string line; std::getline(table, line);) {
        std::istringstream row(line);
        double seconds = 0.0, mse = -1.0, relmse = -1.0;
        unsigned spp = 0;
        if (!(row >> seconds >> spp >> mse >> relmse)) continue;
        ++rows;
        if (spp == 4) EXPECT_LT(relmse, 1e-9) << line; // float rounding of the sRGB curve alone
    }
    EXPECT_GE(rows, 2) << r.out;
}

TEST_F(Cli, HostilePathsAreNamedAndLeaveNoOutput) {
    const fs::path odd = dir_ / "a folder with spaces and ünïcödé";
    fs::create_directories(odd);
    fs::copy_file(kCornell, odd / "cornell böx.gltf");
    const test::ProcessResult r = run("render '" + (odd / "cornell böx.gltf").string() +
                                      "' --width 16 --spp 1 -o '" + (odd / "ëxr out.exr").string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(odd / "ëxr out.exr"));

    const std::string small = "render " + kCornell + " --width 16 --spp 1 ";
    expect_rejected(small + "-o " + path("no/such/folder/x.png"), "no/such/folder");
    write("plain.txt", "not a folder");
    expect_rejected(small + "-o " + path("plain.txt/x.png"), "plain.txt");
    expect_rejected(small + "-o " + path("x.unknownformat"), "x.unknownformat");
    for (const char* name : {"x.png", "x.unknownformat"}) EXPECT_FALSE(fs::exists(path(name)));

    // A buffer outside the scene's folder is not read, even where it exists.
    fs::create_directories(dir_ / "scene");
    write("outside.bin", std::string(36, '\0'));
    write("scene/escape.gltf",
          R"({"asset":{"version":"2.0"},"buffers":[{"uri":"../outside.bin","byteLength":36}],)"
          R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
          R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}],)"
          R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})");
    expect_rejected("render " + path("scene/escape.gltf") + " -o " + path("escape.png"), "outside the scene's folder");
    EXPECT_FALSE(fs::exists(path("escape.png")));
}

// Every file a render would write is checked before any work: a folder where
// the file should be, a missing folder, a read-only file, for the image, the
// partial render beside it, the CSV report and the statistics. Nothing is
// created, and no temporary is left behind.
TEST_F(Cli, EveryOutputPathIsCheckedBeforeRendering) {
    const std::string small = "render " + kCornell + " --width 16 --spp 1 ";
    for (const char* folder : {"taken.exr", "out.exr.partial.exr", "report.csv", "stats.json"})
        fs::create_directories(dir_ / folder);
    write("stdout.txt", "");
    write("stderr.txt", "");
    auto listing = [&] {
        std::set<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) names.insert(entry.path().filename().string());
        return names;
    };
    const std::set<std::string> before = listing();
    expect_rejected(small + "-o " + path("taken.exr"), "taken.exr: is a folder");
    expect_rejected(small + "-o " + path("out.exr"), "out.exr.partial.exr: is a folder");
    expect_rejected(small + "-o " + path("a.exr") + " --report " + path("report.csv"), "report.csv: is a folder");
    expect_rejected(small + "-o " + path("a.exr") + " --stats-json " + path("stats.json"), "stats.json: is a folder");
    expect_rejected(small + "-o " + path("a.exr") + " --stats-json " + path("none/stats.json"), "none/stats.json");
    expect_rejected(small + "-o " + path("a.exr") + " --report " + path("none/r.csv"), "none/r.csv");
    if (::geteuid() != 0) { // root writes through any file mode
        write("locked.exr", "old");
        fs::permissions(dir_ / "locked.exr", fs::perms::owner_read);
        expect_rejected(small + "-o " + path("locked.exr"), "locked.exr: the file there is read-only");
    }
    if (::geteuid() != 0) fs::remove(dir_ / "locked.exr");
    EXPECT_EQ(listing(), before); // nothing made, no temporary left
}

TEST_F(Cli, ReportsErrorAgainstTimeAsCsv) {
    const std::string small = "render " + kCornell + " --width 24 --height 24 ";
    ASSERT_EQ(run(small + "--spp 64 -o " + path("ref.exr")).exit_code, 0);
    const test::ProcessResult r = run(small + "--spp 16 --reference " + path("ref.exr") + " --report " + path("r.csv") +
                                " -o " + path("x.exr"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string csv = test::read_file(path("r.csv"));
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "seconds,spp,mse,relmse,mae,relmse_estimate");
    // A checkpoint at each doubling, every error column filled in but the
    // estimate at 1 spp (one sample has no variance).
    std::istringstream rows(csv.substr(csv.find('\n') + 1));
    std::vector<int> spp;
    for (std::string row; std::getline(rows, row);) {
        spp.push_back(std::stoi(row.substr(row.find(',') + 1)));
        EXPECT_EQ(row.find(",,"), std::string::npos) << row;
        EXPECT_EQ(row.back() == ',', spp.back() == 1) << row;
    }
    EXPECT_EQ(spp, (std::vector<int>{1, 2, 4, 8, 16}));

    expect_rejected(small + "--spp 4 --reference " + path("ref.exr") + " --width 25 -o " + path("y.exr"), "ref.exr");
    EXPECT_FALSE(fs::exists(path("y.exr")));
}

TEST_F(Cli, StopsAtTheTimeBudgetOrTheTargetError) {
    const std::string small = "render " + kCornell + " --width 24 --height 24 ";
    ASSERT_EQ(run(small + "--time 1 --report " + path("t.csv") + " -o " + path("t.exr")).exit_code, 0);
    const std::string csv = test::read_file(path("t.csv"));
    std::istringstream rows(csv.substr(csv.find('\n') + 1));
    std::vector<double> seconds;
    int spp = 0;
    for (std::string row; std::getline(rows, row);) {
        seconds.push_back(std::stod(row));
        spp = std::stoi(row.substr(row.find(',') + 1));
    }
    ASSERT_GE(seconds.size(), 2u) << csv;
    EXPECT_GT(spp, 16) << "open-ended: --time without --spp is not capped at the default";
    // A round starts only while time is left, and is sized to what is left;
    // bounded by this run's own round times, not by a wall-clock figure, so a
    // loaded machine cannot fail it.
    double longest_round = 0.0;
    for (size_t i = 0; i + 1 < seconds.size(); ++i) {
        EXPECT_LT(seconds[i], 1.0) << csv;
        longest_round = std::max(longest_round, seconds[i] - (i ? seconds[i - 1] : 0.0));
    }
    EXPECT_LT(seconds.back(), 1.0 + 4.0 * longest_round + 0.5) << csv;
    auto in = OIIO::ImageInput::open(path("t.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_int_attribute("wavefront:samplesPerPixel"), spp);

    ASSERT_EQ(run(small + "--target-error 0.05 --report " + path("e.csv") + " -o " + path("e.exr")).exit_code, 0);
    const std::string errors = test::read_file(path("e.csv"));
    const std::string final_row = errors.substr(errors.rfind('\n', errors.size() - 2) + 1);
    EXPECT_LT(std::stod(final_row.substr(final_row.rfind(',') + 1)), 0.05) << errors;
}

TEST_F(Cli, ChecksInByTimeWithReportEvery) {
    ASSERT_EQ(run("render " + kCornell + " --width 24 --height 24 --time 1.2 --report-every 0.3 --report " +
                  path("every.csv") + " -o " + path("every.exr"))
                  .exit_code,
              0);
    std::istringstream rows(test::read_file(path("every.csv")));
    std::string row;
    std::getline(rows, row); // header
    std::vector<int> spp;
    std::vector<double> seconds;
    while (std::getline(rows, row)) {
        seconds.push_back(std::stod(row));
        spp.push_back(std::stoi(row.substr(row.find(',') + 1)));
    }
    // The first round (1 spp) measures the rate; then a round that starts with
    // more than 0.3 s of the budget left lasts about 0.3 s, and those after it
    // fill what is left. The rate is re-measured each round and another test
    // may share the cores, so a round may run long or short by a factor of a
    // few: the bounds say "by time", not how precisely.
    EXPECT_GE(spp.size(), 3u);
    EXPECT_LE(spp.size(), 16u);
    EXPECT_TRUE(std::is_sorted(spp.begin(), spp.end()));
    for (size_t i = 2; i < seconds.size() && seconds[i - 1] < 1.2 - 0.3; ++i)
        EXPECT_GT(seconds[i] - seconds[i - 1], 0.3 / 4) << "row " << i;
}

TEST_F(Cli, WritesBounceLayersToExr) {
    const std::string small = "render " + kCornell + " --width 16 --height 16 --spp 2 --aov bounces ";
    ASSERT_EQ(run(small + "-o " + path("layers.exr")).exit_code, 0);
    auto in = OIIO::ImageInput::open(path("layers.exr"));
    ASSERT_TRUE(in);
    const std::vector<std::string>& names = in->spec().channelnames;
    ASSERT_EQ(names.size(), 27u);
    EXPECT_EQ(names[3], "bounce0.R");
    EXPECT_EQ(names[26], "bounce7plus.B");
    expect_rejected(small + "-o " + path("layers.png"), "layers.png");
    expect_rejected("render " + kCornell + " --sampler halton", "--sampler: halton not in {independent,sobol}");
    expect_rejected("render " + kCornell + " --time -3", "--time: -3 is not above 0");
}

TEST_F(Cli, EnvironmentFlagsLightAScene) {
    Image map;
    map.width = 16;
    map.height = 8;
    map.rgb.assign(size_t{map.width} * map.height * 3, 0.5f);
    write_image(path("sky.exr"), map, ImageMetadata{});
    const std::string box = WF_SOURCE_DIR "/../shared/scenes-real/Box/Box.gltf";
    const std::string small = "render '" + box + "' --width 16 --height 16 --spp 2 ";
    const test::ProcessResult lit =
        run(small + "--env " + path("sky.exr") + " --env-rotate -30 --env-scale 2 -o " + path("lit.exr"));
    ASSERT_EQ(lit.exit_code, 0) << lit.err;
    EXPECT_NE(lit.out.find("an environment"), std::string::npos) << lit.out;
    EXPECT_EQ(lit.err.find("no light"), std::string::npos) << lit.err;

    // Without --env the box has no light: it is lit all the same, and says so.
    const test::ProcessResult unlit = run(small + "-o " + path("unlit.exr"));
    ASSERT_EQ(unlit.exit_code, 0) << unlit.err;
    EXPECT_NE(unlit.err.find("no light"), std::string::npos) << unlit.err;
    const Image image = read_image(path("unlit.exr"));
    double sum = 0.0;
    for (float v : image.rgb) sum += v;
    EXPECT_GT(sum, 0.0);

    const test::ProcessResult uniform = run(small + "--env-uniform 0.5 -o " + path("uniform.exr"));
    ASSERT_EQ(uniform.exit_code, 0) << uniform.err;
    EXPECT_NE(uniform.out.find("an environment"), std::string::npos) << uniform.out;
    // --env-uniform 0 asks for no environment at all: the unlit box stays black.
    const test::ProcessResult black = run(small + "--env-uniform 0 -o " + path("black.exr"));
    ASSERT_EQ(black.exit_code, 0) << black.err;
    EXPECT_EQ(black.err.find("uniform white"), std::string::npos) << black.err;
    for (float v : read_image(path("black.exr")).rgb) ASSERT_EQ(v, 0.0f);
    expect_rejected(small + "--env-uniform -1 -o " + path("x.exr"), "--env-uniform: -1 is below 0");
    expect_rejected(small + "--env " + path("sky.exr") + " --env-uniform 1 -o " + path("x.exr"), "--env-uniform");
    expect_rejected(small + "--env " + path("missing.exr") + " -o " + path("x.exr"), "missing.exr");
    expect_rejected(small + "--env-scale 2 -o " + path("x.exr"), "--env");
    expect_rejected(small + "--env " + path("sky.exr") + " --env-scale -1 -o " + path("x.exr"), "--env-scale");
    expect_rejected(small + "--env " + path("sky.exr") + " --env-rotate nan -o " + path("x.exr"), "--env-rotate");
}

} // namespace
} // namespace wf
