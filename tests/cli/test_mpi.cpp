// test_mpi.cpp — `mpirun -np N wavefront render`: 1, 2 and 3 ranks (one PoCL
// thread each, oversubscribed on the CI's two cores) give the bytes of one
// process; Ctrl-C on mpirun writes the image and the partial render, which
// goes on with any rank count to the uninterrupted bytes; a rank killed
// mid-render is named and ends the run, never hangs it; a rank whose set-up
// fails or differs from rank 0's is named. Skipped in a build without MPI.
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "film/partial_render.h"
#include "image/image_io.h"
#include "support/scratch_folder.h"
#include "support/test_support.h"

namespace wf {
namespace {

namespace fs = std::filesystem;
const std::string kCornell = WF_SOURCE_DIR "/scenes/cornell-box.gltf";
// CI runs as root; one PoCL thread a rank. mpirun ends the ranks a second
// after Ctrl-C by default: three here, for a loaded machine
// (docs/devices.md). Shared memory without single-copy, which a container may
// forbid (process_vm_readv).
const std::string kMpiEnv = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 POCL_MAX_PTHREAD_COUNT=1 "
                            "OMPI_MCA_odls_base_sigkill_timeout=3 OMPI_MCA_btl_vader_single_copy_mechanism=none";

class Mpi : public test::ScratchFolder {
protected:
    void SetUp() override {
#ifndef WF_HAVE_MPI
        GTEST_SKIP() << "built without MPI";
#endif
        ScratchFolder::SetUp();
    }

    std::string render_args(const std::string& output, uint32_t spp) const {
        return "render " + kCornell + " --width 64 --seed 8 --spp " + std::to_string(spp) + " --cache-dir " +
               path("cache") + " -o " + output;
    }
    // `mpirun -np ranks wavefront ARGS` (or an MPMD line given whole), its output in the test's folder.
    std::string mpirun(int ranks, const std::string& args) const {
        return "mpirun --oversubscribe -np " + std::to_string(ranks) + " " + WF_BINARY + " " + args;
    }
    test::ProcessResult run(const std::string& command) const {
        const std::string out = path("stdout.txt"), err = path("stderr.txt");
        const int status = std::system(("env " + kMpiEnv + " " + command + " > " + out + " 2> " + err).c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::read_file(out), test::read_file(err)};
    }
    // Started in the background; mpirun's pid.
    pid_t start(const std::string& command) const {
        const std::string line = "exec env " + kMpiEnv + " " + command + " > " + path("stdout.txt") + " 2> " +
                                 path("stderr.txt");
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::execl("/bin/sh", "sh", "-c", line.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        return pid;
    }
    // Its exit code, -1 for a signal, or -2 when it had not ended in `seconds` (then killed).
    static int wait_for(pid_t pid, int seconds = 300) {
        int status = 0;
        for (int i = 0; i < seconds * 20; ++i, std::this_thread::sleep_for(std::chrono::milliseconds(50)))
            if (::waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
        return -2;
    }
    static bool appears(const std::string& file) {
        for (int i = 0; i < 1200; ++i, std::this_thread::sleep_for(std::chrono::milliseconds(100)))
            if (fs::exists(file)) return true;
        return false;
    }
};

bool same_pixels(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

TEST_F(Mpi, OneTwoAndThreeRanksGiveTheBytesOfOneProcess) {
    const test::ProcessResult single = test::run_wavefront(render_args(path("single.exr"), 12), dir_.string());
    ASSERT_EQ(single.exit_code, 0) << single.err;
    for (int ranks : {1, 2, 3}) {
        const std::string output = path("ranks" + std::to_string(ranks) + ".exr");
        const test::ProcessResult r = run(mpirun(ranks, render_args(output, 12)));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_TRUE(same_pixels(read_image(path("single.exr")), read_image(output))) << ranks << " ranks";
        if (ranks > 1) {
            EXPECT_NE(r.out.find("on " + std::to_string(ranks) + " MPI ranks"), std::string::npos) << r.out;
            EXPECT_NE(r.out.find("rank " + std::to_string(ranks - 1) + ": "), std::string::npos) << r.out;
        }
    }
}

// --look-at and --fov shape the camera every rank renders through, not only rank 0's.
TEST_F(Mpi, EveryRankRendersTheCommandLinesCamera) {
    const std::string camera = " --look-at 400,300,-600,278,273,0 --fov 50";
    const test::ProcessResult single =
        test::run_wavefront(render_args(path("single.exr"), 4) + camera, dir_.string());
    ASSERT_EQ(single.exit_code, 0) << single.err;
    const test::ProcessResult r = run(mpirun(2, render_args(path("ranks2.exr"), 4) + camera));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(same_pixels(read_image(path("single.exr")), read_image(path("ranks2.exr"))));
}

// Ctrl-C reaches mpirun, which passes SIGTERM to every rank: rank 0 writes
// the image and the partial render; resumed on three ranks and on one, it
// ends with the bytes of a render never stopped.
TEST_F(Mpi, CtrlCWritesThePartialRenderAndAnyRankCountGoesOn) {
    const std::string stopped = path("stopped.exr"), partial = partial_render_path(stopped);
    const pid_t pid = start(mpirun(2, render_args(stopped, 1u << 20) + " --checkpoint-every 0.3"));
    ASSERT_TRUE(appears(partial)) << "no checkpoint while rendering";
    ::kill(pid, SIGINT);
    EXPECT_NE(wait_for(pid), -2) << "mpirun did not end";
    const std::string err = test::read_file(path("stderr.txt"));
    ASSERT_NE(err.find("--resume " + partial), std::string::npos) << err;
    ASSERT_TRUE(fs::exists(stopped));
    const PartialRender p = read_partial_render(partial);
    const uint32_t most = *std::max_element(p.film.samples.begin(), p.film.samples.end());
    fs::copy_file(partial, path("kept.partial.exr"));

    const uint32_t spp = most + 4;
    ASSERT_EQ(test::run_wavefront(render_args(path("direct.exr"), spp), dir_.string()).exit_code, 0);
    const test::ProcessResult three =
        run(mpirun(3, render_args(path("three.exr"), spp) + " --resume " + path("kept.partial.exr")));
    ASSERT_EQ(three.exit_code, 0) << three.err;
    EXPECT_TRUE(same_pixels(read_image(path("direct.exr")), read_image(path("three.exr"))));
    const test::ProcessResult one =
        test::run_wavefront(render_args(path("one.exr"), spp) + " --resume " + path("kept.partial.exr"), dir_.string());
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_TRUE(same_pixels(read_image(path("direct.exr")), read_image(path("one.exr"))));
}

// Rank 1 is killed mid-render: mpirun ends the run naming it, and rank 0,
// stopped by mpirun, still writes what it has.
TEST_F(Mpi, AKilledRankIsNamedAndNothingHangs) {
    const std::string output = path("killed.exr");
    const pid_t pid = start(mpirun(2, render_args(output, 1u << 20) + " --checkpoint-every 0.3"));
    ASSERT_TRUE(appears(partial_render_path(output))) << "no checkpoint while rendering";
    pid_t rank1 = 0;
    for (const auto& entry : fs::directory_iterator("/proc")) {
        const std::string environ = test::read_file((entry.path() / "environ").string());
        const std::string cmdline = test::read_file((entry.path() / "cmdline").string());
        if (cmdline.find(output) != std::string::npos && cmdline.rfind("mpirun", 0) != 0 &&
            environ.find(std::string("OMPI_COMM_WORLD_RANK=1") + '\0') != std::string::npos)
            rank1 = std::stoi(entry.path().filename().string());
    }
    ASSERT_GT(rank1, 0) << "rank 1's process not found";
    ::kill(rank1, SIGKILL);
    const int status = wait_for(pid);
    ASSERT_NE(status, -2) << "the run hung after rank 1 died";
    EXPECT_NE(status, 0);
    const std::string err = test::read_file(path("stderr.txt"));
    EXPECT_NE(err.find("rank 1"), std::string::npos) << err;
}

// Each rank loads the scene itself: one that cannot, or renders another
// image, is named by its rank, and nothing is written.
TEST_F(Mpi, ARankThatCannotJoinIsNamed) {
    const std::string output = path("never.exr");
    const std::string good = std::string(WF_BINARY) + " " + render_args(output, 4);
    test::ProcessResult r =
        run("mpirun --oversubscribe -np 1 " + good + " : -np 1 " + WF_BINARY + " render " + path("missing.gltf") +
            " --width 64 --spp 4 -o " + output);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("error: rank 1: " + path("missing.gltf")), std::string::npos) << r.err;
    r = run("mpirun --oversubscribe -np 1 " + good + " : -np 1 " + WF_BINARY + " render " + kCornell +
            " --width 32 --spp 4 -o " + output);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("error: rank 1 renders 32x32, not rank 0's 64x64"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(output));
}

} // namespace
} // namespace wf
