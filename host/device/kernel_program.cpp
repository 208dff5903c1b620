// kernel_program.cpp — clBuildProgram with the log turned into a readable error.
#include "device/kernel_program.h"

#include <chrono>
#include <sstream>

#include "base/errors.h"
#include "device/kernel_sources.h"

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
                                   const std::string& options, const ProgramCache* cache) {
    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const std::string source = expand_kernel_source(source_path);
    const std::string all_options = "-cl-std=CL1.2 " + options;
    const std::string key = cache ? program_cache_key(device.info, all_options, source) : std::string();
    KernelProgram result;
    if (cache) {
        if (const auto binary = cache->load(key)) {
            try {
                result.program = cl::Program(device.context, {device.info.device}, cl::Program::Binaries{*binary});
                result.program.build({device.info.device}, all_options.c_str());
                result.from_cache = true;
                result.build_seconds = seconds();
                return result;
            } catch (const cl::Error&) {
                // A binary the driver will not load (a driver update it cannot see): compile instead.
            }
        }
    }
    result.program = cl::Program(device.context, source);
    try {
        result.program.build({device.info.device}, all_options.c_str());
    } catch (const cl::Error&) {
        const std::string log = result.program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device.info.device);
        throw DeviceError("kernel " + source_path + " failed to build on " + device.info.name + ": " +
                          first_error_line(log));
    }
    if (cache) {
        const auto binaries = result.program.getInfo<CL_PROGRAM_BINARIES>();
        if (!binaries.empty() && !binaries.front().empty()) cache->store(key, binaries.front());
    }
    result.build_seconds = seconds();
    return result;
}

} // namespace wf
