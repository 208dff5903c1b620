// kernel_program.h — compiling an embedded kernel source for one device.
#pragma once

#include <string>

#include "device/opencl_device.h"
#include "device/program_cache.h"

namespace wf {

struct KernelProgram {
    cl::Program program;
    double build_seconds = 0.0;
    bool from_cache = false; // the binary came from `cache`, not the compiler
};

// Builds kernels/<source_path> (includes expanded) with `options`, taking the
// binary from `cache` when it holds this exact program and storing it there
// otherwise. Throws DeviceError with the first error line of the build log
// when it fails.
KernelProgram build_kernel_program(const OpenClDevice& device, const std::string& source_path,
                                   const std::string& options = "", const ProgramCache* cache = nullptr);

} // namespace wf
