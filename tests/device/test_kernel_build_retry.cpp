// test_kernel_build_retry.cpp — a kernel build that fails without naming an
// error in the source (PoCL's cache written by several processes at once,
// bench/pocl_cache_race.sh) is tried once more, with a warning; one that names
// an error is not (host/device/kernel_program.h).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "device/kernel_program.h"

namespace wf {
namespace {

const char* const kPoclCacheFailure = "Device pthread-skylake-avx512-AMD EPYC failed to build the program\n";
const char* const kSourceError = "<kernel>:12:5: error: use of undeclared identifier 'x'\n";

// An attempt that returns `logs` in turn ("" is a build that worked), counting its calls.
struct ScriptedBuild {
    std::vector<std::string> logs;
    size_t calls = 0;
    std::string operator()() { return logs.at(calls++); }
};

TEST(KernelBuildRetry, AFailureNamingNoErrorIsRetriedOnceWithAWarning) {
    ScriptedBuild build{{kPoclCacheFailure, ""}};
    std::string warning;
    EXPECT_EQ(build_retrying_once(std::ref(build), "kernel wavefront.cl on cpu", &warning), "");
    EXPECT_EQ(build.calls, 2u);
    EXPECT_NE(warning.find("kernel wavefront.cl on cpu: the first build failed without naming an error"),
              std::string::npos)
        << warning;
    EXPECT_NE(warning.find("failed to build the program"), std::string::npos) << warning;
}

TEST(KernelBuildRetry, ASourceErrorFailsAtOnce) {
    ScriptedBuild build{{kSourceError, ""}};
    std::string warning;
    EXPECT_EQ(build_retrying_once(std::ref(build), "kernel", &warning), kSourceError);
    EXPECT_EQ(build.calls, 1u);
    EXPECT_TRUE(warning.empty());
}

TEST(KernelBuildRetry, TwoFailuresReportTheSecondWithoutAWarning) {
    ScriptedBuild build{{kPoclCacheFailure, kPoclCacheFailure}};
    std::string warning;
    EXPECT_EQ(build_retrying_once(std::ref(build), "kernel", &warning), kPoclCacheFailure);
    EXPECT_EQ(build.calls, 2u);
    EXPECT_TRUE(warning.empty());
}

TEST(KernelBuildRetry, AWorkingBuildRunsOnce) {
    ScriptedBuild build{{""}};
    std::string warning;
    EXPECT_EQ(build_retrying_once(std::ref(build), "kernel", &warning), "");
    EXPECT_EQ(build.calls, 1u);
    EXPECT_TRUE(warning.empty());
}

} // namespace
} // namespace wf
