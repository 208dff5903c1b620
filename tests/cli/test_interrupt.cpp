// test_interrupt.cpp — long renders as a user lives with them: Ctrl-C and
// SIGTERM write what was computed and exit 128 + signal; --checkpoint-every
// keeps a partial render on disk while it runs; --resume goes on from one to
// the bytes of a render never stopped, and refuses one made with other options
// or from another scene; a stop before any sample replaces nothing.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <thread>
#include <fstream>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "film/partial_render.h"
#include "support/scratch_folder.h"
#include "support/test_support.h"

namespace wf {
namespace {

namespace fs = std::filesystem;
const std::string kCornell = WF_SOURCE_DIR "/scenes/cornell-box.gltf";

class Interrupt : public test::ScratchFolder {
protected:

    // Starts `wavefront render` with `args` (one word each), its output in the test's folder.
    pid_t start(const std::vector<std::string>& args) const {
        const std::string out = path("stdout.txt"), err = path("stderr.txt");
        const pid_t pid = ::fork();
        if (pid == 0) {
            std::vector<const char*> argv{WF_BINARY, "render"};
            for (const std::string& a : args) argv.push_back(a.c_str());
            argv.push_back(nullptr);
            std::freopen(out.c_str(), "w", stdout);
            std::freopen(err.c_str(), "w", stderr);
            ::execv(WF_BINARY, const_cast<char* const*>(argv.data()));
            ::_exit(127);
        }
        return pid;
    }
    // Waits for it; its exit code, or -1 when a signal ended it.
    static int wait_for(pid_t pid) {
        int status = 0;
        ::waitpid(pid, &status, 0);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    // Waits until `file` exists (at most 60 s).
    static bool appears(const std::string& file) {
        for (int i = 0; i < 600; ++i, std::this_thread::sleep_for(std::chrono::milliseconds(100)))
            if (fs::exists(file)) return true;
        return false;
    }
    std::vector<std::string> render_args(const std::string& output, uint32_t spp) const {
        return {kCornell, "--width", "96", "--spp", std::to_string(spp), "--seed", "5", "--cache-dir",
                path("cache"), "--pool-size", "1000", "--quiet", "-o", output};
    }

    void interrupt_and_resume(const std::vector<std::string>& extra);
};

bool same_pixels(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

// Ctrl-C during a render with `extra` flags, then --resume to beyond what it
// had, against the same count rendered in one go.
void Interrupt::interrupt_and_resume(const std::vector<std::string>& extra) {
    const std::string stopped = path("stopped.exr"), partial = partial_render_path(stopped);
    auto with_extra = [&](std::vector<std::string> args) {
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    std::vector<std::string> args = with_extra(render_args(stopped, 1u << 20));
    args.erase(std::find(args.begin(), args.end(), "--quiet")); // it says how to go on
    args.insert(args.end(), {"--checkpoint-every", "0.3"});
    const pid_t pid = start(args);
    ASSERT_TRUE(appears(partial)) << "no checkpoint while rendering";
    // A checkpoint read while the render goes on is whole: files are renamed into place.
    EXPECT_NO_THROW(read_partial_render(partial));
    ::kill(pid, SIGINT);
    EXPECT_EQ(wait_for(pid), 128 + SIGINT) << test::read_file(path("stderr.txt"));
    EXPECT_NE(test::read_file(path("stderr.txt")).find("--resume " + partial), std::string::npos);

    const PartialRender p = read_partial_render(partial);
    EXPECT_NO_THROW(check_partial_options(p, partial, {{"seed", "5"}}));
    const uint32_t least = *std::min_element(p.film.samples.begin(), p.film.samples.end());
    const uint32_t most = *std::max_element(p.film.samples.begin(), p.film.samples.end());
    ASSERT_GE(least, 1u);
    // A slot owns pixels slot, slot + 1000, ...: the paths in flight were
    // finished and none started after, so its pixels are at most one apart.
    for (size_t pixel = 1000; pixel < p.film.samples.size(); ++pixel) {
        ASSERT_LE(p.film.samples[pixel], p.film.samples[pixel - 1000]) << pixel;
        ASSERT_LE(p.film.samples[pixel % 1000], p.film.samples[pixel] + 1) << pixel;
    }
    EXPECT_TRUE(test::all_finite(read_image(stopped)));

    const uint32_t spp = most + 3;
    const std::string resumed = path("resumed.exr"), direct = path("direct.exr");
    std::vector<std::string> resume = with_extra(render_args(resumed, spp));
    resume.insert(resume.end(), {"--resume", partial});
    ASSERT_EQ(wait_for(start(resume)), 0) << test::read_file(path("stderr.txt"));
    ASSERT_EQ(wait_for(start(with_extra(render_args(direct, spp)))), 0) << test::read_file(path("stderr.txt"));
    EXPECT_TRUE(same_pixels(read_image(resumed), read_image(direct)));
}

TEST_F(Interrupt, CtrlCWritesThePartialImageAndResumingGivesTheUninterruptedBytes) { interrupt_and_resume({}); }

TEST_F(Interrupt, TheMegakernelResumesToTheUninterruptedBytes) {
    interrupt_and_resume({"--integrator", "megakernel"});
}

TEST_F(Interrupt, ResumeRefusesAPartialRenderOfOtherOptions) {
    const std::string stopped = path("stopped.exr"), partial = partial_render_path(stopped);
    std::vector<std::string> args = render_args(stopped, 1u << 20);
    args.insert(args.end(), {"--checkpoint-every", "0.2"});
    const pid_t pid = start(args);
    ASSERT_TRUE(appears(partial)) << "no checkpoint while rendering"; // it renders: its handlers are in place
    ::kill(pid, SIGTERM);
    ASSERT_EQ(wait_for(pid), 128 + SIGTERM);
    ASSERT_TRUE(fs::exists(partial));
    args = render_args(path("other.exr"), 64);
    args[6] = "6"; // --seed
    args.insert(args.end(), {"--resume", partial});
    EXPECT_EQ(wait_for(start(args)), 2);
    EXPECT_NE(test::read_file(path("stderr.txt")).find("was rendered with seed '5'"), std::string::npos)
        << test::read_file(path("stderr.txt"));
    EXPECT_FALSE(fs::exists(path("other.exr")));
}

// The first signal asks for a clean stop, which writes the image; the second
// ends the process at once, with 128 + its number and no image. Two signals of
// one kind could merge while pending, so two kinds are sent; on a loaded
// machine both may be pending together, and Linux then delivers the lower
// number (SIGINT) first, so either may be the second. No clock is involved.
TEST_F(Interrupt, ASecondSignalEndsAtOnce) {
    const std::string output = path("out.exr");
    std::vector<std::string> args = render_args(output, 1u << 20);
    args[2] = "256"; // --width: a stop that takes a while to finish cleanly
    args.insert(args.end(), {"--checkpoint-every", "0.2"});
    const pid_t pid = start(args);
    ASSERT_TRUE(appears(partial_render_path(output))) << "no checkpoint while rendering";
    ::kill(pid, SIGTERM);
    ::kill(pid, SIGINT);
    const int status = wait_for(pid);
    EXPECT_TRUE(status == 128 + SIGINT || status == 128 + SIGTERM) << "exit " << status;
    EXPECT_FALSE(fs::exists(output)) << "the clean stop went on after the second signal";
}

// --resume asks for more samples than the partial holds, finds the scene by
// its contents wherever it now lies, refuses an edited one, says where it went
// on from, and removes the partial once the image is whole.
TEST_F(Interrupt, ResumeGoesOnFromTheSameSceneAndCleansUp) {
    const std::string stopped = path("stopped.exr"), partial = partial_render_path(stopped);
    std::vector<std::string> args = render_args(stopped, 1u << 20);
    args.insert(args.end(), {"--checkpoint-every", "0.2"});
    const pid_t pid = start(args);
    ASSERT_TRUE(appears(partial)) << "no checkpoint while rendering";
    ::kill(pid, SIGINT);
    ASSERT_EQ(wait_for(pid), 128 + SIGINT);
    const PartialRender p = read_partial_render(partial);
    const uint32_t held = *std::min_element(p.film.samples.begin(), p.film.samples.end());

    auto resume_args = [&](const std::string& scene, uint32_t spp) {
        std::vector<std::string> a = render_args(stopped, spp);
        a[0] = scene;
        a.insert(a.end(), {"--resume", partial});
        return a;
    };
    EXPECT_EQ(wait_for(start(resume_args(kCornell, held))), 2);
    EXPECT_NE(test::read_file(path("stderr.txt")).find("already holds " + std::to_string(held) + " spp"),
              std::string::npos)
        << test::read_file(path("stderr.txt"));

    std::string edited = test::read_file(kCornell);
    edited.replace(edited.find("\"asset\""), 7, "\"extras\":{},\"asset\"");
    std::ofstream(path("edited.gltf")) << edited;
    EXPECT_EQ(wait_for(start(resume_args(path("edited.gltf"), held + 4))), 2);
    EXPECT_NE(test::read_file(path("stderr.txt")).find("was rendered from another scene"), std::string::npos)
        << test::read_file(path("stderr.txt"));

    fs::copy_file(kCornell, path("moved.gltf"));
    std::vector<std::string> moved = resume_args(path("moved.gltf"), held + 4);
    moved.erase(std::find(moved.begin(), moved.end(), "--quiet"));
    ASSERT_EQ(wait_for(start(moved)), 0) << test::read_file(path("stderr.txt"));
    EXPECT_NE(test::read_file(path("stdout.txt")).find(std::to_string(held + 4) + " spp (resumed from " +
                                                       std::to_string(held) + ")"),
              std::string::npos)
        << test::read_file(path("stdout.txt"));
    EXPECT_FALSE(fs::exists(partial)) << "the partial outlived the whole image";
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().filename().string().find(".writing-"), std::string::npos) << entry.path();
}

// A signal before any sample finished (here, while the kernels compile into an
// empty cache) writes nothing: the image already there stays as it was.
TEST_F(Interrupt, AStopBeforeAnySampleReplacesNothing) {
    const std::string output = path("kept.exr");
    std::ofstream(output) << "an earlier render";
    std::vector<std::string> args = render_args(output, 64);
    args.erase(std::find(args.begin(), args.end(), "--quiet"));
    std::string words = "render";
    for (const std::string& a : args) words += " '" + a + "'";
    // On a terminal it says when it starts building; its handlers are in place by then.
    bool signalled = false;
    const test::ProcessResult r =
        test::run_wavefront_on_terminal(words, dir_.string(), [&](const std::string& seen, pid_t pid) {
            if (!signalled && seen.find("building the render") != std::string::npos) signalled = ::kill(pid, SIGINT) == 0;
        });
    const std::string& seen = r.out;
    ASSERT_TRUE(signalled) << seen;
    EXPECT_EQ(r.exit_code, 128 + SIGINT) << seen;
    EXPECT_NE(seen.find("interrupted before any sample finished: nothing written"), std::string::npos) << seen;
    EXPECT_EQ(test::read_file(output), "an earlier render");
    EXPECT_FALSE(fs::exists(partial_render_path(output)));
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().filename().string().find(".writing-"), std::string::npos) << entry.path();
}

TEST_F(Interrupt, AFinishedRenderLeavesNoPartialFile) {
    const std::string output = path("out.png");
    std::vector<std::string> args = render_args(output, 32);
    args.insert(args.end(), {"--checkpoint-every", "0.01"});
    ASSERT_EQ(wait_for(start(args)), 0) << test::read_file(path("stderr.txt"));
    EXPECT_TRUE(fs::exists(output));
    EXPECT_FALSE(fs::exists(partial_render_path(output)));
    for (const auto& entry : fs::directory_iterator(dir_)) // nor a temporary one
        EXPECT_EQ(entry.path().filename().string().find(".writing-"), std::string::npos) << entry.path();
}

} // namespace
} // namespace wf
