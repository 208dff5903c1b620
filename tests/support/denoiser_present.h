// denoiser_present.h — for the tests that need Open Image Denoise
// (image/denoiser.h): where the library is absent they are skipped with a
// message saying how to install it, unless WF_REQUIRE_OIDN=1 (as in CI,
// .ci/run, where scripts/setup.sh has installed it): then they fail.
#pragma once

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "image/denoiser.h"

#define WF_SKIP_WITHOUT_OIDN()                                                                                     \
    do {                                                                                                           \
        std::string wf_oidn_missing;                                                                               \
        if (!::wf::denoiser_available(&wf_oidn_missing)) {                                                         \
            const char* wf_required = std::getenv("WF_REQUIRE_OIDN");                                              \
            if (wf_required && std::string(wf_required) == "1")                                                    \
                FAIL() << "WF_REQUIRE_OIDN=1 but " << wf_oidn_missing;                                             \
            GTEST_SKIP() << "denoising not tested: " << wf_oidn_missing;                                           \
        }                                                                                                          \
    } while (false)
