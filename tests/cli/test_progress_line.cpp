// test_progress_line.cpp — the progress a long render shows on stderr: what
// one line holds, that a log gets whole lines and a terminal one line
// rewritten, and that --quiet leaves stderr empty.
#include <chrono>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "cli/progress_line.h"
#include "support/test_support.h"

namespace wf {
namespace {

RenderStats some_progress() {
    RenderStats stats;
    stats.samples = 2'500'000;
    stats.closest_rays = 6'000'000;
    stats.shadow_rays = 3'000'000;
    return stats;
}

TEST(ProgressLine, ALogGetsWholeLinesWithCountsRatesAndTimes) {
    std::ostringstream log;
    ProgressLine line(log, /*terminal=*/false, /*period=*/0.0, /*total_samples=*/10'000'000, /*time_budget=*/0.0);
    line.set_error(1.5e-3);
    line.update(some_progress());
    line.finish();
    const std::string text = log.str();
    EXPECT_EQ(text.find('\r'), std::string::npos) << text;
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(text.back(), '\n');
    for (const char* part : {"2.5 M samples of 10.0 M (25.0%)", "M rays/s", "elapsed 0:00:", "left ", "relMSE est. 1.50e-03"})
        EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in " << text;
}

TEST(ProgressLine, ATerminalGetsOneLineRewrittenAndClearedAtTheEnd) {
    std::ostringstream tty;
    ProgressLine line(tty, /*terminal=*/true, 0.0, 0, /*time_budget=*/60.0);
    line.update(some_progress()); // the first update may come before the period: nothing yet
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    line.update(some_progress());
    line.finish();
    const std::string text = tty.str();
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
    EXPECT_NE(text.find("\r\33[Krender: 2.5 M samples, "), std::string::npos) << text;
    EXPECT_NE(text.find(", left 0:0"), std::string::npos) << text; // what is left of the budget
    EXPECT_EQ(text.substr(text.size() - 4), "\r\33[K");
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
