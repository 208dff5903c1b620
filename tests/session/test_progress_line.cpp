// test_progress_line.cpp — the progress a long render shows on stderr: what
// one line holds, that a log gets whole lines and a terminal one line
// rewritten and erased before anything else is printed, and that --quiet
// leaves stderr empty.
#include <sstream>

#include <gtest/gtest.h>

#include "session/progress_line.h"
#include "support/test_support.h"

namespace wf {
namespace {

// A render that goes on from `start_spp` samples, within `time_budget` seconds (0: none).
ProgressOptions progress_from(uint32_t start_spp, double time_budget = 0.0) {
    ProgressOptions progress;
    progress.start_spp = start_spp;
    progress.time_budget = time_budget;
    return progress;
}

RenderStats some_progress() {
    RenderStats stats;
    stats.samples = 2'500'000;
    stats.closest_rays = 6'000'000;
    stats.shadow_rays = 3'000'000;
    return stats;
}

TEST(ProgressLine, ALogGetsWholeLinesWithSppRatesAndTimes) {
    std::ostringstream log;
    // 2.5 M samples over 78125 pixels: 32 spp of 128.
    ProgressLine line(log, /*terminal=*/false, /*period=*/0.0, /*pixels=*/78'125, /*spp=*/128, progress_from(0));
    line.set_error(1.5e-3);
    line.update(some_progress());
    line.clear();
    const std::string text = log.str();
    EXPECT_EQ(text.find('\r'), std::string::npos) << text;
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(text.back(), '\n');
    for (const char* part : {"render: 32/128 spp, ", "M rays/s", "elapsed 0:00:", "left ", "relMSE est. 1.50e-03"})
        EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in " << text;
}

TEST(ProgressLine, AResumedRenderCountsFromWhereItStarted) {
    std::ostringstream log;
    ProgressLine line(log, false, 0.0, 250'000, 64, progress_from(40));
    line.update(some_progress()); // 10 spp more
    EXPECT_NE(log.str().find("render: 50/64 spp (resumed from 40), "), std::string::npos) << log.str();
}

TEST(ProgressLine, ATerminalGetsOneLineRewrittenAndErasedForOtherOutput) {
    std::ostringstream tty;
    ProgressLine line(tty, /*terminal=*/true, /*period=*/1e9, 250'000, /*spp=*/0, progress_from(0, /*time_budget=*/60.0));
    line.update(some_progress()); // before the period: nothing yet
    EXPECT_EQ(tty.str(), "");
    line.clear(); // nothing on screen: nothing to erase
    EXPECT_EQ(tty.str(), "");

    ProgressLine shown(tty, true, 0.0, 250'000, 0, progress_from(0, 60.0));
    shown.update(some_progress());
    EXPECT_EQ(tty.str().rfind("\r\33[Krender: 10 spp, ", 0), 0u) << tty.str();
    EXPECT_NE(tty.str().find(", left 0:0"), std::string::npos) << tty.str(); // what is left of the budget
    shown.clear(); // a checkpoint row is about to be printed
    EXPECT_EQ(tty.str().substr(tty.str().size() - 4), "\r\33[K");
    const std::string text = tty.str();
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
}

// Both streams on one terminal, as a user sees them: every checkpoint row
// starts on a line of its own, never after a progress line.
TEST(ProgressLine, CheckpointRowsNeverLandInTheProgressLine) {
    const std::string dir = ::testing::TempDir();
    const test::ProcessResult r = test::run_wavefront_on_terminal(
        std::string("render ") + WF_SOURCE_DIR "/scenes/cornell-box.gltf --width 64 --spp 64 -o " + dir + "/tty.png",
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.out;
    // What the terminal shows: after every erase, either a progress line or a row.
    size_t rows = 0;
    std::istringstream lines(r.out);
    for (std::string l; std::getline(lines, l);) {
        const size_t last_erase = l.rfind("\33[K");
        const std::string visible = last_erase == std::string::npos ? l : l.substr(last_erase + 3);
        if (visible.find("spp") == std::string::npos && visible.find_first_not_of(" .0123456789e-+\r") == std::string::npos &&
            !visible.empty())
            ++rows;
        EXPECT_EQ(visible.find("render: "), std::string::npos) << "a line left a progress line behind: " << l;
    }
    EXPECT_GE(rows, 6u) << r.out; // the checkpoint rows at 1, 2, 4, ..., 64 spp
}

TEST(ProgressLine, QuietLeavesStderrEmpty) {
    const std::string dir = ::testing::TempDir();
    const test::ProcessResult r = test::run_wavefront(
        std::string("render ") + WF_SOURCE_DIR "/scenes/cornell-box.gltf --width 16 --spp 2 --quiet -o " + dir +
            "/quiet.png",
        dir);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.err, "");
}

} // namespace
} // namespace wf
