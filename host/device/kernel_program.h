// kernel_program.h — compiling an embedded kernel source for one device.
#pragma once

#include <functional>
#include <string>

#include "device/opencl_device.h"
#include "device/program_cache.h"

namespace wf {

struct KernelProgram {
    cl::Program program;
    double build_seconds = 0.0;
    bool from_cache = false; // the binary came from `cache`, not the compiler
    std::string warning;     // a first build that failed and was retried, when one did
};

// Builds kernels/<source_path> (includes expanded) with `options`, taking the
// binary from `cache` when it holds this exact program and storing it there
// otherwise. A build whose log names no error in the source is tried once
// more (build_retrying_once). Throws DeviceError with the first error line of
// the build log when it fails.
KernelProgram build_kernel_program(const OpenClDevice& device, const std::string& source_path,
                                   const std::string& options = "", const ProgramCache* cache = nullptr);

// Runs `attempt`, which returns "" when the build worked and its log when it
// failed, a second time when the first log names no error in the source: PoCL
// 3.1 fails that way now and then when processes build the same program into
// one cache folder at once (bench/pocl_cache_race.sh: 5 of 352 cold processes,
// 16 at a time, failed before; none of 160 with the retry). Returns "" and sets
// *warning when the second try worked; else the log of the last try.
std::string build_retrying_once(const std::function<std::string()>& attempt, const std::string& what,
                                std::string* warning);

} // namespace wf
