// scratch_folder.h — a test fixture with a folder of its own, for tests that
// run the program and read what it writes: made empty under the system's
// temporary folder before each test, named by the process, suite and test so
// that parallel tests never share it, and removed after.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

#include <gtest/gtest.h>

namespace wf::test {

class ScratchFolder : public ::testing::Test {
protected:
    void SetUp() override {
        const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() / ("wavefront-" + std::to_string(::getpid()) + "-" +
                                                         test->test_suite_name() + "-" + test->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ignored; // nothing to remove where SetUp skipped the test first
        std::filesystem::remove_all(dir_, ignored);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    std::filesystem::path dir_;
};

} // namespace wf::test
