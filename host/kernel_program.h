// kernel_program.h — compiling an embedded kernel source for one device.
#pragma once

#include <string>

#include "opencl_device.h"

namespace wf {

struct KernelProgram {
    cl::Program program;
    double build_seconds = 0.0;
};

// Builds kernels/<source_path> (includes expanded) with `options`. Throws
// DeviceError with the first error line of the build log when it fails.
KernelProgram build_kernel_program(const OpenClDevice& device, const std::string& source_path,
                                   const std::string& options = "");

} // namespace wf
