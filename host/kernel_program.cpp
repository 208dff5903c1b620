// kernel_program.cpp — clBuildProgram with the log turned into a readable error.
#include "kernel_program.h"

#include <chrono>
#include <sstream>

#include "errors.h"
#include "kernel_sources.h"

namespace wf {
namespace {

std::string first_error_line(const std::string& log) {
    std::istringstream in(log);
    std::string line, first_nonempty;
    while (std::getline(in, line)) {
        if (line.find("error") != std::string::npos) return line;
        if (first_nonempty.empty() && !line.empty()) first_nonempty = line;
    }
    return first_nonempty;
}

} // namespace

KernelProgram build_kernel_program(const OpenClDevice& device, const std::string& source_path,
                                   const std::string& options) {
    const auto start = std::chrono::steady_clock::now();
    KernelProgram result;
    result.program = cl::Program(device.context, expand_kernel_source(source_path));
    try {
        result.program.build({device.info.device}, ("-cl-std=CL1.2 " + options).c_str());
    } catch (const cl::Error&) {
        const std::string log = result.program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device.info.device);
        throw DeviceError("kernel " + source_path + " failed to build on " + device.info.name + ": " +
                          first_error_line(log));
    }
    result.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace wf
